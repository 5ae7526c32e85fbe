#pragma once
/// @file
/// File > Import motion capture… and the Capture panel's "Import settings…": the flags of
/// `saltus import` the capture advice names, as controls — the frame time (the file's, or one
/// given; the library's suggestion one click away), the flight (found from the feet, or START
/// to END in the clip's seconds), the keyframes (the library's pick, a count, or every frame)
/// and a mapping file for skeletons whose names no built-in convention knows. The library checks
/// the values when it imports (its messages name the flag).

#include <QDialog>
#include <optional>

#include "saltus/use_cases/captures.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace saltus::gui {

class CaptureImportDialog : public QDialog {
  Q_OBJECT

 public:
  /// Starts from `options` (the defaults, or those of the import shown); `stated_frame_time`
  /// (s, 0: unknown) and `suggested_frame_time` (the library's, none: no button) say what the
  /// file states and what the import found.
  CaptureImportDialog(const QString& capture, const CaptureFileOptions& options,
                      double stated_frame_time, std::optional<double> suggested_frame_time,
                      QWidget* parent = nullptr);

  /// The options the controls say (the model is left to the app: the model in use).
  CaptureFileOptions options() const;

  // The controls (tests set them).
  QCheckBox* frame_time_given() const { return frame_time_given_; }
  QDoubleSpinBox* frame_time() const { return frame_time_; }
  QPushButton* use_suggestion() const { return use_suggestion_; }
  QCheckBox* flight_given() const { return flight_given_; }
  QDoubleSpinBox* flight_start() const { return flight_start_; }
  QDoubleSpinBox* flight_end() const { return flight_end_; }
  QComboBox* keyframes() const { return keyframes_; }
  QSpinBox* keyframe_count() const { return keyframe_count_; }
  QLineEdit* mapping() const { return mapping_; }

 private:
  void update_enabled();

  CaptureFileOptions base_;
  QCheckBox* frame_time_given_ = nullptr;
  QDoubleSpinBox* frame_time_ = nullptr;
  QPushButton* use_suggestion_ = nullptr;
  QCheckBox* flight_given_ = nullptr;
  QDoubleSpinBox* flight_start_ = nullptr;
  QDoubleSpinBox* flight_end_ = nullptr;
  QComboBox* keyframes_ = nullptr;
  QSpinBox* keyframe_count_ = nullptr;
  QLineEdit* mapping_ = nullptr;
};

}  // namespace saltus::gui
