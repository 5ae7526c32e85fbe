#pragma once
/// @file
/// The Capture panel, for a motion imported from a motion capture (File > Import motion
/// capture…, or a .bvh opened or dropped): what the import found (source, flight phase,
/// take-off fits, implied gravity, the capture's own residual, warnings) and the capture's
/// timeline, one cell per captured flight frame, where a click adds that frame as a keyframe or
/// removes it (and shows the frame); "Pick automatically" and "Every frame" ask for the
/// library's picks. It only asks for edits; the EditController makes them (undoable).

#include <QWidget>
#include <vector>

#include "saltus/use_cases/captures.h"

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace saltus::gui {

class Document;

/// The capture's flight frames in a row: filled = a keyframe of the motion, hollow = not; the
/// first and last are keyframes for good (locked); a line marks the time shown.
class CaptureFrameStrip : public QWidget {
  Q_OBJECT

 public:
  explicit CaptureFrameStrip(QWidget* parent = nullptr);
  /// Frame times (s, the motions' clock) and which frames are keyframes.
  void set_frames(const std::vector<double>& times, const std::vector<int>& picked);
  void set_time(double t);
  int frame_count() const { return static_cast<int>(times_.size()); }
  /// The frame whose cell holds the point (widget coordinates), -1 for none.
  int frame_at(const QPoint& point) const;
  /// The centre of a frame's cell (tests click there).
  QPoint cell_centre(int frame) const;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 signals:
  void frame_clicked(int frame);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  bool event(QEvent* event) override;

 private:
  QRectF cell(int frame) const;

  std::vector<double> times_;
  std::vector<bool> picked_;
  double time_ = 0.0;
};

class CapturePanel : public QWidget {
  Q_OBJECT

 public:
  explicit CapturePanel(QWidget* parent = nullptr);

  /// Shows the document's capture (or says there is none), its picked frames and the residual
  /// with the model in use.
  void set_document(const Document* document);
  void set_time(double t);
  /// A problem with the last edit, or "" to clear it.
  void show_problem(const QString& message);
  QString problem() const;
  CaptureFrameStrip* strip() const { return strip_; }
  /// The words shown about the import and the pick (tests read them).
  QString summary() const;
  /// The fixes' buttons shown now (tests click them).
  std::vector<QPushButton*> fix_buttons() const;
  QPushButton* settings_button() const { return settings_; }
  QString pick_text() const;

 signals:
  void frame_toggled(int frame);
  void automatic_requested(bool every_frame);
  void seek_requested(double t);
  /// A fix the import's advice names, one click away (core/capture_fixes.h): import the
  /// capture again with these options.
  void reimport_requested(const saltus::CaptureFileOptions& options);
  /// "Import settings…": the import's options in a dialog.
  void import_settings_requested();

 private:
  QLabel* summary_ = nullptr;
  QLabel* warnings_ = nullptr;
  /// The fixes' buttons, rebuilt with each capture, and "Import settings…".
  QVBoxLayout* fixes_ = nullptr;
  QPushButton* settings_ = nullptr;
  CaptureFrameStrip* strip_ = nullptr;
  QLabel* pick_ = nullptr;
  QPushButton* automatic_ = nullptr;
  QPushButton* every_ = nullptr;
  QLabel* problem_ = nullptr;
  std::vector<double> frame_times_;
};

}  // namespace saltus::gui
