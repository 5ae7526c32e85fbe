#pragma once
/// @file
/// `saltus model new|info|scale|yeadon`: body models of particular athletes. Options and printing
/// only; the models are built, checked and written by the library (use_cases/athlete_models.h).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace saltus_cli {

struct ModelArgs {
  std::string model;  ///< info, scale: a model file or a bundled model's name
  double height = 0.0;
  double mass = 0.0;
  std::string sex;
  double age = 21.0;                    ///< new, yeadon: years, for the strength tables
  std::string strength = "population";  ///< new, yeadon: whose strength
  std::string densities = "dempster";   ///< yeadon
  std::optional<double> yeadon_mass;    ///< yeadon: --mass, when given
  std::string name;
  std::string out_path;
  bool json = false;
  bool quiet = false;
};

struct ModelVerbs {
  ModelArgs new_args;
  ModelArgs info_args;
  ModelArgs scale_args;
  ModelArgs yeadon_args;
  CLI::App* new_command = nullptr;
  CLI::App* yeadon_command = nullptr;
  CLI::App* info_command = nullptr;
  CLI::App* scale_command = nullptr;
};

/// Adds `model` and its subcommands to `app`; `verbs` receives their options and must outlive
/// parsing.
void add_model_verbs(CLI::App& app, ModelVerbs& verbs);

/// Runs whichever was parsed and returns its exit status; nullopt when none was. Bad input
/// throws saltus::InputError (exit status 2 in main).
std::optional<int> run_model_verbs(const ModelVerbs& verbs);

}  // namespace saltus_cli
