#include "app/option_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include "app/qt_text.h"

namespace saltus::gui {

namespace {

/// A text field whose text is acceptable when the option table reads it.
class OptionValidator : public QValidator {
 public:
  OptionValidator(const OptionSpec& spec, QObject* parent) : QValidator(parent), spec_(spec) {}
  State validate(QString& text, int&) const override {
    try {
      parse_option_value(spec_, text.trimmed().toStdString());
      return Acceptable;
    } catch (const OptionValueError&) {
      return Intermediate;
    }
  }

 private:
  const OptionSpec& spec_;
};

}  // namespace

struct OptionForm::Row {
  const OptionSpec* spec = nullptr;
  QWidget* field = nullptr;  ///< what is enabled and disabled
  QCheckBox* check = nullptr;
  QComboBox* choice = nullptr;
  QSpinBox* integer = nullptr;
  QLineEdit* real = nullptr;
};

OptionForm::OptionForm(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 6, 0);  // units clear of the scroll bar
  // Each field below its label, the whole width of the panel column its own: beside the labels
  // ("Objective change tolerance") the fields were a few characters wide and the units
  // ("N²/(N·m)²") were cut at the column's edge, on a laptop and on a 1920×1080 screen alike.
  form->setRowWrapPolicy(QFormLayout::WrapAllRows);
  for (const OptionSpec& spec : option_table()) {
    Row row;
    row.spec = &spec;
    const QString tip = qstr(option_tooltip(spec));
    const std::string name = spec.name;
    switch (spec.kind) {
      case OptionKind::kSwitch:
        row.check = new QCheckBox(qstr(spec.label), this);
        connect(row.check, &QCheckBox::toggled, this, [this, name](bool on) { take(name, on); });
        row.field = row.check;
        form->addRow(QString(), row.check);
        break;
      case OptionKind::kChoice:
        row.choice = new QComboBox(this);
        for (std::size_t i = 0; i < spec.choices.size(); ++i)
          row.choice->addItem(qstr(spec.choice_labels[i]), qstr(spec.choices[i]));
        connect(row.choice, qOverload<int>(&QComboBox::currentIndexChanged), this,
                [this, name, box = row.choice](int) {
                  take(name, box->currentData().toString().toStdString());
                });
        row.field = row.choice;
        break;
      case OptionKind::kInteger: {
        // The word (e.g. "auto") sits just below the range, as the spin box's special value.
        const int low = static_cast<int>(spec.min) - (spec.word.empty() ? 0 : 1);
        row.integer = new QSpinBox(this);
        row.integer->setRange(low, static_cast<int>(spec.max));
        if (!spec.word.empty()) row.integer->setSpecialValueText(qstr(spec.word));
        if (!spec.unit.empty()) row.integer->setSuffix(" " + qstr(spec.unit));
        row.integer->setKeyboardTracking(false);  // a typed value counts when complete
        connect(row.integer, qOverload<int>(&QSpinBox::valueChanged), this,
                [this, name, low, word = spec.word](int v) {
                  if (!word.empty() && v == low)
                    take(name, word);
                  else
                    take(name, v);
                });
        row.field = row.integer;
        break;
      }
      case OptionKind::kReal: {
        row.real = new QLineEdit(this);
        row.real->setValidator(new OptionValidator(spec, row.real));
        connect(row.real, &QLineEdit::editingFinished, this, [this, name, edit = row.real] {
          take(name, parse_option_value(option_spec(name), edit->text().trimmed().toStdString()));
        });
        // Text the table does not read stays red and is not taken.
        connect(row.real, &QLineEdit::textChanged, this, [edit = row.real] {
          edit->setStyleSheet(edit->hasAcceptableInput() ? QString() : "color: #c00000");
        });
        row.field = row.real;
        break;
      }
    }
    row.field->setToolTip(tip);
    row.field->setObjectName(qstr(spec.name));  // for tests and style sheets
    if (spec.kind == OptionKind::kChoice || spec.kind == OptionKind::kInteger) {
      form->addRow(qstr(spec.label), row.field);
    } else if (spec.kind == OptionKind::kReal) {
      auto* line = new QHBoxLayout;
      line->addWidget(row.real, 1);
      if (!spec.unit.empty()) line->addWidget(new QLabel(qstr(spec.unit), this));
      form->addRow(qstr(spec.label), line);
    }
    if (QWidget* label = form->labelForField(row.field)) label->setToolTip(tip);
    rows_.push_back(row);
  }
  show_values();
}

OptionForm::~OptionForm() = default;

void OptionForm::set_values(const OptimizeSettings& values) {
  values_ = values;
  show_values();
}

void OptionForm::set_editable(bool editable) {
  editable_ = editable;
  update_enabled();
}

void OptionForm::take(const std::string& name, const OptionValue& value) {
  if (setting_ || values_.get(name) == value) return;
  const OptimizeSettings before = values_;
  values_.set(name, value);
  update_enabled();
  emit edited(before, values_);
}

void OptionForm::show_values() {
  setting_ = true;
  for (Row& row : rows_) {
    const OptionValue& value = values_.get(row.spec->name);
    if (row.check) row.check->setChecked(std::get<bool>(value));
    if (row.choice)
      row.choice->setCurrentIndex(row.choice->findData(qstr(std::get<std::string>(value))));
    if (row.integer)
      row.integer->setValue(std::holds_alternative<int>(value) ? std::get<int>(value)
                                                               : row.integer->minimum());
    if (row.real) row.real->setText(qstr(option_value_text(value)));
  }
  setting_ = false;
  update_enabled();
}

void OptionForm::update_enabled() {
  for (Row& row : rows_)
    row.field->setEnabled(editable_ && values_.applies(row.spec->name));
}

}  // namespace saltus::gui
