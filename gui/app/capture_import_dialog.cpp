#include "app/capture_import_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "saltus/optim/optimize.h"

namespace saltus::gui {

namespace {

enum KeyframeChoice { kPicked = 0, kCount = 1, kEvery = 2 };

}  // namespace

CaptureImportDialog::CaptureImportDialog(const QString& capture, const CaptureFileOptions& options,
                                         double stated_frame_time,
                                         std::optional<double> suggested_frame_time,
                                         QWidget* parent)
    : QDialog(parent), base_(options) {
  setWindowTitle(tr("Import motion capture"));
  auto* intro = new QLabel(
      tr("<b>%1</b> onto the model in use, as <tt>saltus import</tt> does. Change only what "
         "the Capture panel's advice names; the rest is found from the capture.")
          .arg(QFileInfo(capture).fileName().toHtmlEscaped()),
      this);
  intro->setWordWrap(true);

  // The frame time: the file's, or one given (--frame-time).
  frame_time_given_ = new QCheckBox(tr("Seconds per frame (--frame-time):"), this);
  frame_time_ = new QDoubleSpinBox(this);
  frame_time_->setDecimals(5);
  frame_time_->setRange(1e-5, 10.0);
  frame_time_->setSingleStep(0.001);
  frame_time_->setSuffix(tr(" s"));
  frame_time_->setValue(options.import.frame_time ? *options.import.frame_time
                        : stated_frame_time > 0   ? stated_frame_time
                                                  : 1.0 / 120.0);
  frame_time_given_->setChecked(options.import.frame_time.has_value());
  frame_time_given_->setToolTip(
      stated_frame_time > 0 ? tr("Unchecked: the file's %1 s per frame").arg(stated_frame_time)
                            : tr("Unchecked: the file's frame time"));
  auto* frame_row = new QHBoxLayout;
  frame_row->addWidget(frame_time_, 1);
  if (suggested_frame_time) {
    // The library's suggestion, one click away.
    use_suggestion_ = new QPushButton(tr("Use %1 s (%2 Hz): the flight then falls at g")
                                          .arg(*suggested_frame_time, 0, 'g', 4)
                                          .arg(1.0 / *suggested_frame_time, 0, 'g', 3),
                                      this);
    connect(use_suggestion_, &QPushButton::clicked, this, [this, suggested_frame_time] {
      frame_time_given_->setChecked(true);
      frame_time_->setValue(*suggested_frame_time);
    });
  }

  // The flight: found from the feet, or given in the clip's seconds (--flight START:END).
  flight_given_ = new QCheckBox(tr("Flight from, to (--flight, the clip's seconds):"), this);
  flight_given_->setToolTip(
      tr("Unchecked: from the first frame without ground contact to the "
         "last, as the library finds it from the feet"));
  flight_start_ = new QDoubleSpinBox(this);
  flight_end_ = new QDoubleSpinBox(this);
  for (QDoubleSpinBox* box : {flight_start_, flight_end_}) {
    box->setDecimals(3);
    box->setRange(0.0, 1e5);
    box->setSingleStep(0.01);
    box->setSuffix(tr(" s"));
  }
  if (options.import.flight) {
    flight_start_->setValue(options.import.flight->first);
    flight_end_->setValue(options.import.flight->second);
  }
  flight_given_->setChecked(options.import.flight.has_value());
  auto* flight_row = new QHBoxLayout;
  flight_row->addWidget(flight_start_);
  flight_row->addWidget(new QLabel(tr("to"), this));
  flight_row->addWidget(flight_end_);

  // The keyframes (--keyframes N|all).
  keyframes_ = new QComboBox(this);
  keyframes_->addItem(tr("picked by the library (as few as meet the capture)"));
  keyframes_->addItem(tr("this many, evenly spread:"));
  keyframes_->addItem(tr("every captured frame"));
  keyframe_count_ = new QSpinBox(this);
  keyframe_count_->setRange(2, kMaxOptimizedKeyframes);
  keyframe_count_->setToolTip(
      tr("The optimiser takes at most %1 keyframes").arg(kMaxOptimizedKeyframes));
  keyframe_count_->setValue(options.import.keyframe_count ? *options.import.keyframe_count : 12);
  keyframes_->setCurrentIndex(options.import.all_keyframes    ? kEvery
                              : options.import.keyframe_count ? kCount
                                                              : kPicked);
  auto* keyframe_row = new QHBoxLayout;
  keyframe_row->addWidget(keyframes_, 1);
  keyframe_row->addWidget(keyframe_count_);

  // A mapping file (--mapping).
  mapping_ = new QLineEdit(QString::fromStdString(options.mapping), this);
  mapping_->setPlaceholderText(tr("none: by the joints' names"));
  auto* browse = new QPushButton(tr("Browse…"), this);
  connect(browse, &QPushButton::clicked, this, [this, capture] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Skeleton mapping file"),
                                                      QFileInfo(capture).absolutePath(),
                                                      tr("Mapping files (*.json);;All files (*)"));
    if (!path.isEmpty()) mapping_->setText(path);
  });
  auto* mapping_row = new QHBoxLayout;
  mapping_row->addWidget(mapping_, 1);
  mapping_row->addWidget(browse);

  auto* form = new QFormLayout;
  form->addRow(frame_time_given_, frame_row);
  if (use_suggestion_) form->addRow(QString(), use_suggestion_);
  form->addRow(flight_given_, flight_row);
  form->addRow(tr("Keyframes (--keyframes):"), keyframe_row);
  form->addRow(tr("Mapping (--mapping):"), mapping_row);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(buttons);

  for (QCheckBox* box : {frame_time_given_, flight_given_})
    connect(box, &QCheckBox::toggled, this, &CaptureImportDialog::update_enabled);
  connect(keyframes_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          &CaptureImportDialog::update_enabled);
  update_enabled();
}

void CaptureImportDialog::update_enabled() {
  frame_time_->setEnabled(frame_time_given_->isChecked());
  flight_start_->setEnabled(flight_given_->isChecked());
  flight_end_->setEnabled(flight_given_->isChecked());
  keyframe_count_->setEnabled(keyframes_->currentIndex() == kCount);
}

CaptureFileOptions CaptureImportDialog::options() const {
  CaptureFileOptions o = base_;
  o.import.frame_time.reset();
  if (frame_time_given_->isChecked()) o.import.frame_time = frame_time_->value();
  o.import.flight.reset();
  if (flight_given_->isChecked())
    o.import.flight = std::make_pair(flight_start_->value(), flight_end_->value());
  o.import.keyframe_count.reset();
  o.import.all_keyframes = keyframes_->currentIndex() == kEvery;
  if (keyframes_->currentIndex() == kCount) o.import.keyframe_count = keyframe_count_->value();
  o.mapping = mapping_->text().trimmed().toStdString();
  return o;
}

}  // namespace saltus::gui
