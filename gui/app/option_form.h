#pragma once
/// @file
/// A form with one row per option of the library's option table (saltus/optim/option_table.h):
/// a check box for a switch, a list for a choice, a spin box for a whole number (its word, such
/// as "auto", below the range), a text field for a real number checked by the table's parser.
/// Labels, units, ranges and tooltips all come from the table, so a new option appears here
/// without an edit. Options that have no effect given the others (ε of the relaxed model) are
/// greyed out.

#include <QWidget>
#include <vector>

#include "core/optimize_settings.h"

class QFormLayout;

namespace saltus::gui {

class OptionForm : public QWidget {
  Q_OBJECT

 public:
  explicit OptionForm(QWidget* parent = nullptr);
  ~OptionForm() override;

  /// The values shown; a real number being typed counts once it reads (Enter or leaving it).
  OptimizeSettings values() const { return values_; }
  void set_values(const OptimizeSettings& values);
  /// Whether the fields take input (not while an optimisation runs).
  void set_editable(bool editable);

 signals:
  /// The user changed a value (not emitted by set_values).
  void edited(const saltus::gui::OptimizeSettings& before,
              const saltus::gui::OptimizeSettings& after);

 private:
  struct Row;
  void show_values();
  void update_enabled();
  void take(const std::string& name, const OptionValue& value);

  std::vector<Row> rows_;
  OptimizeSettings values_;
  bool editable_ = true;
  bool setting_ = false;
};

}  // namespace saltus::gui
