// File > New athlete… as a coach uses it: a junior typed into the dialog is the library's de Leva
// model (the preview's figures and heights are the library's), saved through the save dialog
// (answered by the test) with the library's writer, and then flies the open motion like File >
// Open model (the unsaved-work prompt, a fresh undo history, the same take-off spin); a height
// no person has shows the library's message and disables the buttons; a Yeadon measurements file
// builds an athlete; "Save and compare…" and batch --compare with a model file show the motion
// on both athletes side by side, on one scale; "can this athlete land it?" is said first in the
// dialog, the compare window and the Model panel, in the library's words; the source choices,
// Browse… and Cancel pressed with the mouse do what they say.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <filesystem>
#include <fstream>

#include "app/athlete_controller.h"
#include "app/batch.h"
#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/model_panel.h"
#include "app/new_athlete_dialog.h"
#include "core/athlete_landing.h"
#include "gui/support/image_checks.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/body/mass_properties.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/formats/model_file.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/cli_runner.h"
#include "support/junior_athlete.h"

namespace saltus::gui {
namespace {

/// Replaces a field's text by `text` typed on the keyboard.
void type_into(QWidget* field, const QString& text) {
  if (auto* box = qobject_cast<QAbstractSpinBox*>(field)) box->selectAll();
  if (auto* edit = qobject_cast<QLineEdit*>(field)) edit->selectAll();
  QTest::keyClicks(field, text);
  QApplication::processEvents();
}

class NewAthleteTest : public test::OpenMotionTest {
 protected:
  /// The save dialog answered with `answer`; counts the questions.
  void answer_save_dialog(const QString& answer) {
    window_->files().set_save_chooser(
        [this, answer](const QString& title, const QString& suggestion, const QString&) {
          ++asked_;
          title_ = title;
          suggestion_ = suggestion;
          return answer;
        });
  }

  /// File > New athlete…, as the menu triggers it.
  NewAthleteDialog* open_dialog() {
    window_->athletes().new_action()->trigger();
    QApplication::processEvents();
    NewAthleteDialog* dialog = window_->athletes().dialog();
    EXPECT_NE(dialog, nullptr);
    if (dialog) {
      EXPECT_TRUE(QTest::qWaitForWindowExposed(dialog));
    }
    return dialog;
  }

  /// The junior typed in: name, height, mass, sex.
  static void type_junior(NewAthleteDialog* dialog) {
    type_into(dialog->name_edit(), "junior");
    type_into(dialog->height_box(), "1.45");
    type_into(dialog->mass_box(), "38");
    dialog->sex_box()->setCurrentText("female");
    QApplication::processEvents();
  }

  static void press(QPushButton* button) {
    ASSERT_TRUE(button->isEnabled()) << button->text().toStdString();
    QTest::mouseClick(button, Qt::LeftButton);
    QApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  }

  saltus::test::TempDir dir_;
  int asked_ = 0;
  QString title_;
  QString suggestion_;
};

TEST_F(NewAthleteTest, AJuniorIsTheLibrarysModelSavedAndFliesTheOpenMotion) {
  // Unsaved work first: New athlete asks before dropping it, as Open model does.
  std::vector<double> factors(static_cast<std::size_t>(window_->document().file().model.size()),
                              1.0);
  factors[0] = 1.2;
  QString error;
  ASSERT_TRUE(window_->edits().set_mass_factors(factors, &error)) << error.toStdString();
  ASSERT_GT(window_->edits().undo_stack()->count(), 0);
  QString question;
  window_->files().set_discard_prompt([&question](const QString& q) {
    question = q;
    return FileController::DiscardAnswer::kDiscard;
  });

  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  type_junior(dialog);

  // The preview is the library's junior: its figures and its standing height, beside the model
  // in use (1.70 m).
  const BodyModel expected = saltus::test::junior_athlete();
  const StandingBody standing = standing_body(expected);
  ASSERT_TRUE(dialog->draft().model) << dialog->problem().toStdString();
  EXPECT_TRUE(dialog->problem().isEmpty()) << dialog->problem().toStdString();
  EXPECT_DOUBLE_EQ(dialog->draft().model->total_mass(), expected.total_mass());
  EXPECT_NE(dialog->figures().indexOf(QString::asprintf("%.1f kg", expected.total_mass())), -1)
      << dialog->figures().toStdString();
  EXPECT_NE(
      dialog->figures().indexOf(QString::asprintf("standing height %.3f m", standing.height())), -1)
      << dialog->figures().toStdString();
  EXPECT_NE(dialog->figures().indexOf("1.450 m"), -1) << dialog->figures().toStdString();
  const std::vector<double> heights = dialog->preview_heights();
  ASSERT_EQ(heights.size(), 2u);
  EXPECT_DOUBLE_EQ(heights[0], standing.height());
  EXPECT_DOUBLE_EQ(heights[1], standing_body(window_->document().file().model).height());
  const QImage preview = dialog->grab_preview();
  EXPECT_GT(test::blank_check(preview).distinct_colours, 30);
  EXPECT_GT(test::colour_fraction(preview, QColor(64, 120, 224)), 0.002);  // the left limbs
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  dialog->grab().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/new_athlete_dialog.png");

  // Save and use: the save dialog chooses the file, the library writes it.
  const std::string path = dir_ / "junior.model.json";
  answer_save_dialog(QString::fromStdString(path));
  press(dialog->use_button());
  EXPECT_EQ(asked_, 1);
  EXPECT_TRUE(suggestion_.endsWith("junior.model.json")) << suggestion_.toStdString();
  ASSERT_TRUE(std::filesystem::exists(path));
  const BodyModel back = load_body_model(path);
  EXPECT_EQ(back.name, "junior");
  EXPECT_NEAR(back.total_mass(), 38.0, 1e-9);
  EXPECT_DOUBLE_EQ(back.total_mass(), expected.total_mass());

  // The open motion now flies on it, as after File > Open model.
  EXPECT_FALSE(question.isEmpty()) << "the unsaved mass edit was dropped without asking";
  EXPECT_EQ(window_->document().file().model.name, "junior");
  EXPECT_DOUBLE_EQ(window_->document().file().model.total_mass(), expected.total_mass());
  EXPECT_EQ(std::filesystem::path(window_->document().model_override()),
            std::filesystem::absolute(path));
  ASSERT_TRUE(window_->document().file().takeoff_adaptation);
  EXPECT_EQ(window_->document().file().takeoff_adaptation->rule, "same spin");
  EXPECT_EQ(window_->edits().undo_stack()->count(), 0);
  EXPECT_FALSE(window_->workspace().has_unsaved_work());
  EXPECT_EQ(window_->athletes().dialog(), nullptr);  // closed once used
}

TEST_F(NewAthleteTest, AHeightNoPersonHasShowsTheLibrarysMessageAndDisablesTheButtons) {
  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  type_junior(dialog);
  ASSERT_TRUE(dialog->use_button()->isEnabled());
  type_into(dialog->height_box(), "3.5");
  EXPECT_FALSE(dialog->draft().model);
  EXPECT_TRUE(dialog->problem().startsWith("Height:")) << dialog->problem().toStdString();
  EXPECT_NE(dialog->problem().indexOf("3.5 m"), -1) << dialog->problem().toStdString();
  EXPECT_FALSE(dialog->use_button()->isEnabled());
  EXPECT_FALSE(dialog->compare_button()->isEnabled());
  EXPECT_TRUE(dialog->figures().isEmpty());
  dialog->grab().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/new_athlete_dialog_bad_height.png");
  // A mass for which no person of this height exists names the mass.
  type_into(dialog->height_box(), "1.45");
  type_into(dialog->mass_box(), "200");
  EXPECT_TRUE(dialog->problem().startsWith("Mass:")) << dialog->problem().toStdString();
  EXPECT_FALSE(dialog->use_button()->isEnabled());
  // Fixed again: the buttons come back.
  type_into(dialog->mass_box(), "38");
  EXPECT_TRUE(dialog->problem().isEmpty());
  EXPECT_TRUE(dialog->use_button()->isEnabled());

  // A cancelled save dialog writes nothing and keeps the dialog and the open model.
  answer_save_dialog(QString());
  press(dialog->use_button());
  EXPECT_EQ(asked_, 1);
  EXPECT_EQ(window_->athletes().dialog(), dialog);
  EXPECT_EQ(window_->document().file().model.name, "zatsiorsky-66kg");
  EXPECT_TRUE(std::filesystem::is_empty(dir_.path()));
  dialog->reject();
}

TEST_F(NewAthleteTest, AYeadonMeasurementsFileBuildsAnAthlete) {
  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  dialog->yeadon_choice()->setChecked(true);
  const std::string file = std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-female1.txt";
  type_into(dialog->measurements_edit(), QString::fromStdString(file));
  dialog->densities_box()->setCurrentText("chandler");
  QApplication::processEvents();
  ASSERT_TRUE(dialog->draft().model) << dialog->problem().toStdString();
  const YeadonModel library = yeadon_athlete_model(file, "chandler", 0.0, "");
  EXPECT_EQ(dialog->draft().model->name, "yeadon-female1");
  EXPECT_DOUBLE_EQ(dialog->draft().model->total_mass(), library.model.total_mass());
  EXPECT_FALSE(dialog->draft().warnings.empty());  // the file's typing errors (README)
  EXPECT_TRUE(dialog->use_button()->isEnabled());
  EXPECT_NE(dialog->figures().indexOf(QString::asprintf("%.1f kg", library.model.total_mass())),
            -1);
  EXPECT_DOUBLE_EQ(dialog->preview_heights().at(0), standing_body(library.model).height());
  dialog->grab().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/new_athlete_dialog_yeadon.png");

  // A given mass scales the densities to it.
  type_into(dialog->yeadon_mass_box(), "55");
  ASSERT_TRUE(dialog->draft().model) << dialog->problem().toStdString();
  EXPECT_NEAR(dialog->draft().model->total_mass(), 55.0, 1e-6);

  // A broken file: the library's message naming it, no athlete.
  const std::string broken = dir_ / "broken-measurements.txt";
  std::ofstream(broken) << "Ls1L: 15.2\nLa2L: oops\n";
  type_into(dialog->measurements_edit(), QString::fromStdString(broken));
  EXPECT_FALSE(dialog->draft().model);
  EXPECT_NE(dialog->problem().indexOf("broken-measurements.txt"), -1)
      << dialog->problem().toStdString();
  EXPECT_FALSE(dialog->use_button()->isEnabled());
  dialog->reject();
}

TEST_F(NewAthleteTest, TheSourceChoicesBrowseAndCancelDoWhatTheySay) {
  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  type_junior(dialog);
  ASSERT_TRUE(dialog->draft().model);
  const double junior_mass = dialog->draft().model->total_mass();

  // "From Yeadon's 95 measurements": the file fields open, the size fields close, and with no
  // file yet there is no athlete.
  QTest::mouseClick(dialog->yeadon_choice(), Qt::LeftButton, Qt::NoModifier,
                    QPoint(8, dialog->yeadon_choice()->height() / 2));
  QApplication::processEvents();
  EXPECT_EQ(dialog->request().source, AthleteRequest::Source::kYeadon);
  EXPECT_TRUE(dialog->measurements_edit()->isEnabled());
  EXPECT_FALSE(dialog->height_box()->isEnabled());
  EXPECT_FALSE(dialog->draft().model);
  EXPECT_FALSE(dialog->use_button()->isEnabled());

  // Browse… fills the file chosen in the file dialog, and the athlete is that file's.
  QPushButton* browse = nullptr;
  for (QPushButton* b : dialog->findChildren<QPushButton*>())
    if (b->text() == "Browse…") browse = b;
  ASSERT_NE(browse, nullptr);
  const QString file = QString(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-female1.txt";
  test::answer_file_dialog([browse] { QTest::mouseClick(browse, Qt::LeftButton); }, file);
  QApplication::processEvents();
  EXPECT_EQ(QFileInfo(dialog->measurements_edit()->text()).canonicalFilePath(),
            QFileInfo(file).canonicalFilePath());
  ASSERT_TRUE(dialog->draft().model) << dialog->problem().toStdString();
  const YeadonModel library = yeadon_athlete_model(
      file.toStdString(), dialog->densities_box()->currentText().toStdString(), 0.0, "junior");
  EXPECT_DOUBLE_EQ(dialog->draft().model->total_mass(), library.model.total_mass());
  EXPECT_NE(dialog->draft().model->total_mass(), junior_mass);
  EXPECT_TRUE(dialog->use_button()->isEnabled());

  // "From height, mass and sex": back to the junior typed before.
  QTest::mouseClick(dialog->size_choice(), Qt::LeftButton, Qt::NoModifier,
                    QPoint(8, dialog->size_choice()->height() / 2));
  QApplication::processEvents();
  EXPECT_EQ(dialog->request().source, AthleteRequest::Source::kSize);
  EXPECT_TRUE(dialog->height_box()->isEnabled());
  ASSERT_TRUE(dialog->draft().model);
  EXPECT_DOUBLE_EQ(dialog->draft().model->total_mass(), junior_mass);

  // Cancel closes the dialog: no save dialog, no file, the open model kept.
  answer_save_dialog(QString::fromStdString(dir_ / "never.model.json"));
  QAbstractButton* cancel =
      dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Cancel);
  ASSERT_NE(cancel, nullptr);
  press(qobject_cast<QPushButton*>(cancel));
  EXPECT_EQ(window_->athletes().dialog(), nullptr);
  EXPECT_EQ(asked_, 0);
  EXPECT_TRUE(std::filesystem::is_empty(dir_.path()));
  EXPECT_EQ(window_->document().file().model.name, "zatsiorsky-66kg");
}

/// Share of a view's pixels in the left limbs' blue: a smaller athlete on one scale covers less.
double left_limbs_share(const QImage& view) {
  return test::colour_fraction(view, QColor(64, 120, 224));
}

TEST_F(NewAthleteTest, SaveAndCompareShowsTheMotionOnBothAthletesOnOneScale) {
  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  type_junior(dialog);
  const std::string path = dir_ / "junior.model.json";
  answer_save_dialog(QString::fromStdString(path));
  press(dialog->compare_button());
  ASSERT_TRUE(std::filesystem::exists(path));
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  // The open motion keeps its model; the compare window flies it on both.
  EXPECT_EQ(window_->document().file().model.name, "zatsiorsky-66kg");
  EXPECT_EQ(compare->run(0).document->file().model.name, "zatsiorsky-66kg");
  EXPECT_EQ(compare->run(1).document->file().model.name, "junior");
  // The take-off by the CLI's rule, and said so.
  const MotionFile cli =
      load_motion_for_athlete(window_->document().file().path, path, TakeoffRule::kSameSpin);
  ASSERT_TRUE(compare->run(1).document->file().motion.takeoff.angular_momentum);
  EXPECT_EQ(*compare->run(1).document->file().motion.takeoff.angular_momentum,
            *cli.motion.takeoff.angular_momentum);
  EXPECT_EQ(compare->run(0).label.toStdString(), "zatsiorsky-66kg 1.70 m 65.5 kg");
  EXPECT_EQ(compare->run(1).label.toStdString(), "junior 1.45 m 38 kg, same take-off spin");
  EXPECT_EQ(compare->force_chart().lines.at(1).label, "junior 1.45 m 38 kg, same take-off spin");

  // One scale: at take-off the junior (1.45 m) is drawn smaller than the 1.70 m athlete, about
  // (1.45/1.70)² of the area, not framed to the same size.
  compare->resize(1400, 900);
  ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
  compare->seek(0.0);
  QApplication::processEvents();
  const double adult = left_limbs_share(compare->grab_view(0));
  const double junior = left_limbs_share(compare->grab_view(1));
  ASSERT_GT(adult, 0.002);
  EXPECT_LT(junior, 0.85 * adult) << "junior " << junior << ", adult " << adult;
  EXPECT_GT(junior, 0.5 * adult) << "junior " << junior << ", adult " << adult;
  compare->grab_window().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/compare_two_athletes.png");
}

TEST_F(NewAthleteTest, CanTheJuniorLandM7IsSaidFirstInTheDialogTheCompareWindowAndTheModelPanel) {
  // The case: M7 on a 1.45 m, 38 kg junior with the same take-off spin turns 1¾
  // somersaults and lands 171° off. The dialog, the compare window and the Model panel say so
  // before anything that could read as success, in the library's words.
  QString error;
  ASSERT_TRUE(window_->open_motion(
      SALTUS_EXAMPLES_DIR "/motions/M7-double-front-one-and-a-half-twists.motion.json", &error))
      << error.toStdString();
  NewAthleteDialog* dialog = open_dialog();
  ASSERT_NE(dialog, nullptr);
  type_junior(dialog);
  const AthleteLanding* landing = dialog->landing();
  ASSERT_NE(landing, nullptr);
  const AthleteLanding expected =
      athlete_landing(motion_on_athlete(window_->document().file(), saltus::test::junior_athlete()),
                      window_->document().evaluate_options());
  EXPECT_FALSE(landing->verdict.lands);
  EXPECT_EQ(landing->verdict.light, VerdictLight::kRed);
  EXPECT_EQ(landing->verdict.headline, expected.verdict.headline);
  EXPECT_EQ(dialog->landing_headline().toStdString(), expected.verdict.headline);
  EXPECT_TRUE(dialog->landing_headline().startsWith("Does not land it"));
  EXPECT_NE(dialog->landing_details().indexOf(
                QString::fromStdString(expected.verdict.flight_words).toHtmlEscaped()),
            -1)
      << dialog->landing_details().toStdString();
  EXPECT_NE(dialog->landing_details().indexOf(
                QString::fromStdString(expected.verdict.strength_words).toHtmlEscaped()),
            -1);
  // Both free flights drawn at landing.
  const QImage landed = dialog->grab_landing();
  EXPECT_GT(test::blank_check(landed).distinct_colours, 20);
  QApplication::processEvents();  // the words' new heights laid out
  dialog->grab().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/new_athlete_junior_M7.png");

  // Save and compare: each side's verdict leads its title, each free flight drawn beside it.
  const std::string path = dir_ / "junior.model.json";
  answer_save_dialog(QString::fromStdString(path));
  press(dialog->compare_button());
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  ASSERT_TRUE(compare->run(1).landing);
  EXPECT_EQ(compare->run(1).landing->verdict.headline, expected.verdict.headline);
  EXPECT_NE(compare->title(1).indexOf("Does not land it"), -1) << compare->title(1).toStdString();
  EXPECT_NE(compare->title(0).indexOf("Lands it"), -1) << compare->title(0).toStdString();
  compare->resize(1366, 768);
  compare->seek(compare->run(0).document->duration());
  QApplication::processEvents();
  compare->grab_window().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/compare_junior_M7.png");
  window_->compare().close();

  // The Model panel with the junior in use says it too.
  ASSERT_TRUE(window_->files().open_model(QString::fromStdString(path), &error))
      << error.toStdString();
  window_->show_model_panel();
  QApplication::processEvents();
  const QString said = window_->edits().model_panel()->landing_text();
  EXPECT_NE(said.indexOf("Can this athlete land it?"), -1) << said.toStdString();
  const AthleteVerdict on_junior =
      athlete_verdict(window_->document().file(), window_->document().evaluate_options());
  EXPECT_EQ(on_junior.light, VerdictLight::kRed) << on_junior.headline;
  EXPECT_NE(said.indexOf(QString::fromStdString(on_junior.headline).toHtmlEscaped()), -1)
      << said.toStdString();
  EXPECT_NE(said.indexOf(QString::fromStdString(verdict_html_colour(VerdictLight::kRed))), -1);
  EXPECT_EQ(said.indexOf(QString::fromStdString(verdict_html_colour(VerdictLight::kGreen))), -1)
      << said.toStdString();
}

TEST_F(NewAthleteTest, TheModelPanelShowsTheLibrarysOneVerdictNeverGreenBesideJointsBeyond) {
  // M7 on its own body lands (its root keyframes were read off that body's free flight); the
  // panel's colour and words are the library's verdict, whatever its light: never the green of a
  // landing beside joints beyond the athlete's strength.
  QString error;
  ASSERT_TRUE(window_->open_motion(
      SALTUS_EXAMPLES_DIR "/motions/M7-double-front-one-and-a-half-twists.motion.json", &error))
      << error.toStdString();
  window_->show_model_panel();
  QApplication::processEvents();
  const QString said = window_->edits().model_panel()->landing_text();
  const AthleteVerdict expected =
      athlete_verdict(window_->document().file(), window_->document().evaluate_options());
  EXPECT_TRUE(expected.lands) << expected.headline;
  EXPECT_NE(said.indexOf(QString::fromStdString(expected.headline).toHtmlEscaped()), -1)
      << said.toStdString();
  for (const VerdictLight light : {VerdictLight::kGreen, VerdictLight::kAmber, VerdictLight::kRed})
    EXPECT_EQ(said.indexOf(QString::fromStdString(verdict_html_colour(light))) != -1,
              light == expected.light)
        << verdict_light_name(light) << ": " << said.toStdString();
  for (const std::string& reason : expected.reasons)
    EXPECT_NE(said.indexOf(QString::fromStdString(reason).toHtmlEscaped()), -1) << reason;
  // Green only within the athlete's strength, in the words of `saltus evaluate`.
  const std::vector<JointStrengthPeak>& peaks = expected.strength_peaks;
  const int largest = largest_strength_share(peaks);
  ASSERT_GT(largest, 0);
  EXPECT_EQ(expected.light == VerdictLight::kGreen,
            peaks[static_cast<std::size_t>(largest)].share <= 1.0);
}

TEST_F(NewAthleteTest, BatchCompareWithAModelFileShowsTwoAthletes) {
  const std::string model = dir_ / "junior.model.json";
  write_athlete_model(model, saltus::test::junior_athlete());
  const QString png = QString::fromStdString(dir_ / "two-athletes.png");
  ASSERT_EQ(
      write_compare_screenshot(*window_, QString::fromStdString(model), 0.5, QSize(1400, 900), png),
      0);
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  // A model file is compared as a model (the same motion on another athlete), not as a motion.
  EXPECT_EQ(compare->run(0).document->file().model.name, "zatsiorsky-66kg");
  EXPECT_EQ(compare->run(1).document->file().model.name, "junior");
  EXPECT_EQ(compare->run(1).document->file().path, compare->run(0).document->file().path);
  const QImage picture(png);
  ASSERT_EQ(picture.size(), QSize(1400, 900));
  // Two bodies drawn (the junior's left limbs cover 0.09 % of her view under the verdict's two
  // lines at 1400x900; a view without her, none).
  for (int i = 0; i < 2; ++i)
    EXPECT_GT(left_limbs_share(compare->grab_view(i)), 0.0005) << "view " << i;
}

}  // namespace
}  // namespace saltus::gui
