#pragma once
/// @file
/// Files: the File menu (open a motion or a model, recent files, drag and drop, save the result
/// folder, the edited motion or model, export pictures, plots, animations and the motion for
/// other tools), the window title and the status line. Nothing unsaved is dropped silently:
/// opening another motion or model and closing the window ask first (Save / Discard / Cancel)
/// when the motion or the masses were edited or a run was not saved.

#include <QObject>
#include <QStringList>
#include <functional>
#include <optional>
#include <string>

#include "app/app_context.h"
#include "core/shown_motion.h"

class QAction;
class QDragEnterEvent;
class QDropEvent;
class QLabel;
class QMenu;
class QToolBar;

namespace saltus::gui {

class PlotsPanel;
class SceneWidget;
class ViewController;
class PlaybackController;

class FileController : public QObject, public RemembersSettings {
  Q_OBJECT

 public:
  FileController(AppContext& context, ViewController& view, PlaybackController& playback,
                 PlotsPanel& plots, QObject* parent = nullptr);

  /// The File menu; `new_model` goes after Open model (New athlete), `more_exports` after the
  /// picture exports (e.g. Export animation).
  void fill_menu(QMenu* file, QAction* new_model = nullptr,
                 const std::vector<QAction*>& more_exports = {});
  void fill_toolbar(QToolBar* bar);

  // Each returns false on failure; with `error` null the message goes to a dialog (or stderr
  // without a user), else it is stored there.
  /// Opens a motion file (with the model it names, or the model opened before), or imports a
  /// motion capture (.bvh) onto that model. Asks first when unsaved work would be dropped;
  /// false if the user keeps it.
  bool open_motion(const QString& path, QString* error = nullptr);
  /// The same with the options of `saltus import` for a capture (its frame time, flight,
  /// keyframes, mapping; the model is the one in use).
  bool import_capture(const QString& path, const CaptureFileOptions& options,
                      QString* error = nullptr);
  /// The Capture panel's "Import settings…": the open capture's options in a dialog, then
  /// imported again with them. False if cancelled or failed.
  bool ask_import_settings();
  /// Uses this model file for the open motion (reloading it) and for motions opened later.
  bool open_model(const QString& path, QString* error = nullptr);
  /// Writes the CLI's output folder: `saltus optimize`'s for the run shown, else `evaluate`'s.
  bool save_result(const QString& dir, QString* error = nullptr);
  /// Writes the motion on screen as a motion file and reads it back through the library: with a
  /// run shown, its optimised motion; else the keyframes (core/shown_motion.h, motion_to_save).
  bool save_motion(const QString& path, QString* error = nullptr);
  /// Writes the keyframes as given (or edited), whatever is shown.
  bool save_given_keyframes(const QString& path, QString* error = nullptr);
  /// Writes the model in use as a model file (named after the file) and reads it back.
  bool save_model(const QString& path, QString* error = nullptr);
  bool export_view_png(const QString& path, QString* error = nullptr);
  /// File > Export web page…: the flight shown (the run's before and after, or the motion as
  /// given) as one self-contained HTML page, made by the library (use_cases/flight_page.h)
  /// from the files `saltus export --format html` reads, written here to a temporary folder.
  bool export_web_page(const QString& path, QString* error = nullptr);
  /// File > Export motion as: the motion shown (the optimised one when there is a run) in one
  /// of the library's formats (use_cases/motion_exports.h, `format` its --format name) at its
  /// default rate, to `path` (a file, or a folder for MuJoCo and OpenSim).
  bool export_motion_as(const std::string& format, const QString& path, QString* error = nullptr);
  bool export_window_png(const QString& path, QString* error = nullptr);
  /// File > Export lecture figure… and `--lecture-figure`: the stroboscopic side view of the
  /// stage shown (core/lecture_figure.h), `poses` poses, as a PNG (scene/lecture_figure_picture.h).
  bool export_lecture_figure(const QString& path, int poses, QString* error = nullptr);

  /// What the user answers when unsaved work would be dropped.
  enum class DiscardAnswer { kSave, kDiscard, kCancel };
  using DiscardPrompt = std::function<DiscardAnswer(const QString& question)>;
  /// Replaces the question (tests); the default asks in a dialog, or discards without a user.
  void set_discard_prompt(DiscardPrompt prompt) { prompt_ = std::move(prompt); }
  /// Where to save a file: the chosen path, or "" when the user cancels.
  using SaveChooser = std::function<QString(const QString& title, const QString& suggestion,
                                            const QString& filter)>;
  /// Replaces the save dialog of the motion and the model (tests). The default is Qt's save
  /// dialog, which asks before replacing an existing file.
  void set_save_chooser(SaveChooser chooser) { save_chooser_ = std::move(chooser); }
  /// The options of `saltus import` for a capture (`capture`): from `current`, with what the
  /// file states and what the library suggests; none when the user cancels.
  using CaptureSettingsChooser = std::function<std::optional<CaptureFileOptions>(
      const QString& capture, const CaptureFileOptions& current, double stated_frame_time,
      std::optional<double> suggested_frame_time)>;
  /// Replaces the import settings dialog (tests). The default is CaptureImportDialog, or,
  /// without a user, `current` unchanged.
  void set_capture_settings_chooser(CaptureSettingsChooser chooser) {
    capture_settings_ = std::move(chooser);
  }
  /// Asks where to save a file, through that dialog (e.g. a new athlete's model).
  QString choose_save_path(const QString& title, const QString& suggestion,
                           const QString& filter) const {
    return save_chooser_(title, suggestion, filter);
  }

  /// Save motion as… (File menu, the Keyframes panel's button): asks where, the dialog's title
  /// saying which motion it writes, then save_motion. A failure is said in the status bar and
  /// a dialog. False if cancelled or failed.
  bool ask_save_motion();
  /// Save given keyframes as… likewise.
  bool ask_save_given_keyframes();
  /// Save body model as… (File menu, the Model panel's button), likewise.
  bool ask_save_model();
  /// Asks before `action` drops unsaved work; true to go on (saved, discarded or nothing to
  /// lose), false to keep it.
  bool confirm_discard(const QString& action);

  void drag_enter(QDragEnterEvent* event);
  void drop(QDropEvent* event);
  const QStringList& recent() const { return recent_; }

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  void motion_opened();

 private:
  void on_workspace(WorkspaceChange change);
  void add_recent(const QString& path);
  void rebuild_recent_menu();
  QString ask_open_file(const QString& title, const QString& filter);
  /// The folder dialog behind Save result (returns false if the user cancels it).
  bool ask_save_result();
  bool ask_save(const std::optional<MotionToSave>& motion);
  bool write_motion(const QString& path, const MotionToSave& what, QString* error);
  /// Says a failed save in the status bar and, with a user, in a dialog. Returns false.
  bool report_save_failure(const QString& title, const QString& message);

  AppContext& context_;
  ViewController& view_;
  PlaybackController& playback_;
  PlotsPanel& plots_;
  DiscardPrompt prompt_;
  SaveChooser save_chooser_;
  CaptureSettingsChooser capture_settings_;
  std::string model_override_;  ///< model file chosen with "Open model", else ""
  QStringList recent_;
  QLabel* status_line_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QAction* open_ = nullptr;
  QAction* import_capture_ = nullptr;
  QAction* save_result_ = nullptr;
  QAction* save_motion_ = nullptr;
  QAction* save_given_ = nullptr;
  QAction* save_model_ = nullptr;
  std::vector<QAction*> need_motion_;  ///< enabled only with a motion open
};

}  // namespace saltus::gui
