#pragma once
/// @file
/// The Compare menu and the compare window's lifetime: the open motion as shown against before
/// vs after of the run shown, another motion, another body model, or a saved result folder.
/// With another body model and a run shown, the second motion is optimised with the same
/// settings in the background, so that the optimised motions of both models compare (the
/// paper's Fig. 8: how heavier thighs change the loads at the hips).

#include <QObject>
#include <QPointer>
#include <memory>
#include <optional>

#include "app/app_context.h"
#include "core/athlete_landing.h"
#include "core/document.h"

class QAction;
class QMenu;

namespace saltus::gui {

class CompareWindow;
class OptimizationRunner;
class ViewController;

class CompareController : public QObject {
  Q_OBJECT

 public:
  CompareController(AppContext& context, ViewController& view, QObject* parent = nullptr);
  ~CompareController() override;

  /// The Compare menu; `new_athlete` goes after With another body model (New athlete).
  void fill_menu(QMenu* compare, QAction* new_athlete = nullptr);

  // Each loads and evaluates the second run as File > Open would; false (with the library's
  // message) on error.
  /// Before vs after of the run shown.
  bool compare_before_after(QString* error = nullptr);
  /// The open motion vs another motion file (with the model in use).
  bool compare_with_motion(const QString& path, QString* error = nullptr);
  /// The open motion with its model vs the same motion flown by the athlete of this model file
  /// (the take-off by the CLI's rule, Document::load); optimised like the run shown when there
  /// is one (see the file comment). Each run is labelled with its athlete (athlete_label).
  bool compare_with_model(const QString& path, QString* error = nullptr);
  /// The open motion vs a `saltus optimize` (or `evaluate`) output folder.
  bool compare_with_folder(const QString& dir, QString* error = nullptr);
  /// A motion file, a model file or a result folder, whichever `path` is (batch --compare).
  bool compare_with(const QString& path, QString* error = nullptr);

  /// The compare window while it is open, else null.
  CompareWindow* window() const;
  void close();
  /// Whether the second run of a model comparison is still being optimised.
  bool optimising() const;
  /// Keeps the event loop running until that optimisation ends or `timeout_ms` pass.
  bool wait(int timeout_ms);

 signals:
  void second_run_ready();

 private:
  bool show(const QString& first_label, Stage first_stage, const QString& first_description,
            std::shared_ptr<const Document> second, const QString& second_label, Stage second_stage,
            const QString& second_description, QString* error);
  bool load_second(const std::string& motion, const std::string& model, Document* out,
                   QString* error);
  QString stage_label(Stage stage) const;
  QString stage_description(Stage stage) const;
  /// Can the athlete of `document` land its motion (core/athlete_landing.h), with `run`'s
  /// warnings; nullopt (said in the status bar) when the library cannot fly it.
  std::optional<AthleteLanding> landing_of(const Document& document,
                                           const OptimizationResult* run) const;
  void update_actions();

  AppContext& context_;
  ViewController& view_;
  QPointer<CompareWindow> window_;
  OptimizationRunner* runner_ = nullptr;
  /// The second document waiting for its optimisation, and the tag of that run.
  std::shared_ptr<Document> pending_;
  int pending_tag_ = 0;
  QAction* before_after_ = nullptr;
  std::vector<QAction*> need_motion_;
  QAction* close_ = nullptr;
};

}  // namespace saltus::gui
