// Seeded mutation fuzzing of the motion and model readers through the CLI (issue 16, "CI that
// keeps it so"): mutants of every bundled motion, its model and an optimised motion (with a
// stored spline) must each give exit status 0 with finite results, or 2 with one line naming the
// file and the field. Never 1, never a crash, nothing left behind. SALTUS_FUZZ_MUTANTS sets the
// mutants per source (default 200).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::names_in;
using test::read_json;
using json = nlohmann::json;

/// One mutant: the two files' text and what was done to them.
struct Mutant {
  std::string motion;
  std::string model;
  std::string description;
};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  Mutant mutate(const json& motion, const json& model) {
    json m = motion;
    json d = model;
    std::string description;
    const bool on_model = chance(0.25);
    json& target = on_model ? d : m;
    std::string duplicate;  // a key to give twice, applied to the text
    const int count = 1 + static_cast<int>(pick(3));
    for (int k = 0; k < count; ++k) {
      std::string done;
      try {
        done = mutate_tree(target, duplicate);
      } catch (const std::exception&) {
        done = "none (an earlier mutation changed what this one needs)";
      }
      description += (description.empty() ? "" : "; ") + done;
    }
    std::string motion_text = m.dump(1);
    std::string model_text = d.dump(1);
    std::string& text = on_model ? model_text : motion_text;
    if (!duplicate.empty()) {
      // mutate_tree left the marker "<dup>" as a value; give its key twice.
      const std::string marker = "\"" + duplicate + "\": \"<dup>\"";
      const auto at = text.find(marker);
      if (at != std::string::npos)
        text.replace(at, marker.size(), "\"" + duplicate + "\": 1, \"" + duplicate + "\": 2");
    }
    if (chance(0.08)) description += "; " + mutate_text(text);
    return {motion_text, model_text, (on_model ? "model: " : "motion: ") + description};
  }

 private:
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  /// A uniform index in [0, n); 0 when n is 0 (callers check emptiness where it matters).
  std::size_t pick(std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

  static void collect(json& node, const std::string& path,
                      std::vector<std::pair<json*, std::string>>& out) {
    out.emplace_back(&node, path);
    if (node.is_object())
      for (auto it = node.begin(); it != node.end(); ++it)
        collect(it.value(), path + "/" + it.key(), out);
    if (node.is_array())
      for (std::size_t i = 0; i < node.size(); ++i)
        collect(node[i], path + "/" + std::to_string(i), out);
  }

  template <typename Predicate>
  std::pair<json*, std::string> random_node(json& root, Predicate accept) {
    std::vector<std::pair<json*, std::string>> all;
    collect(root, "", all);
    std::vector<std::pair<json*, std::string>> chosen;
    for (const auto& entry : all)
      if (accept(*entry.first)) chosen.push_back(entry);
    if (chosen.empty()) return {nullptr, ""};
    return chosen[pick(chosen.size())];
  }

  std::string mutate_tree(json& root, std::string& duplicate) {
    switch (pick(9)) {
      case 0: {  // an extreme or subtly wrong number; half of them outside the rotations, so
                 // that the few physical fields (take-off, times, masses, knots) are hit often
        const bool physical = chance(0.5);
        std::vector<std::pair<json*, std::string>> all;
        collect(root, "", all);
        std::vector<std::pair<json*, std::string>> numbers;
        for (const auto& entry : all)
          if (entry.first->is_number() &&
              (!physical || entry.second.find("/rotations/") == std::string::npos))
            numbers.push_back(entry);
        if (numbers.empty()) return "none";
        auto [node, path] = numbers[pick(numbers.size())];
        if (!node) return "none";
        const double x = node->get<double>();
        const double values[] = {1e308,   -1e308, 1e-320,   -1e-320, 0.0,  1e30,    -1e30, 1e-9,
                                 x * 1e3, -x,     x + 1e-3, 1e5,     -1.0, x * 0.5, 2 * x, 1e-5};
        const double v = values[pick(std::size(values))];
        *node = v;
        return path + " = " + std::to_string(v);
      }
      case 1: {  // another type
        auto [node, path] = random_node(root, [](const json&) { return true; });
        if (!node || path.empty()) return "none";
        const json values[] = {"x", nullptr, true, json::array(), json::object(), 7};
        *node = values[pick(std::size(values))];
        return path + " = " + node->dump();
      }
      case 2: {  // a key removed
        auto [node, path] =
            random_node(root, [](const json& j) { return j.is_object() && !j.empty(); });
        if (!node) return "none";
        auto it = node->begin();
        std::advance(it, static_cast<long>(pick(node->size())));
        const std::string key = it.key();
        node->erase(key);
        return "erase " + path + "/" + key;
      }
      case 3: {  // a key misspelt
        auto [node, path] =
            random_node(root, [](const json& j) { return j.is_object() && !j.empty(); });
        if (!node) return "none";
        auto it = node->begin();
        std::advance(it, static_cast<long>(pick(node->size())));
        const std::string key = it.key();
        std::string typo = key;
        const std::size_t at = pick(typo.size() + 1);
        if (chance(0.5) && !typo.empty())
          typo.erase(std::min(at, typo.size() - 1), 1);
        else
          typo.insert(at, 1, static_cast<char>('a' + pick(26)));
        json value = (*node)[key];
        node->erase(key);
        (*node)[typo] = value;
        return "rename " + path + "/" + key + " -> " + typo;
      }
      case 4: {  // an array shortened, lengthened or given a copy
        auto [node, path] =
            random_node(root, [](const json& j) { return j.is_array() && !j.empty(); });
        if (!node) return "none";
        const std::size_t i = pick(node->size());
        switch (pick(3)) {
          case 0:
            node->erase(i);
            return "erase " + path + "/" + std::to_string(i);
          case 1:
            node->insert(node->begin() + static_cast<long>(i), (*node)[i]);
            return "duplicate " + path + "/" + std::to_string(i);
          default:
            node->push_back(0.5);
            return "append to " + path;
        }
      }
      case 5: {  // a key given twice
        auto [node, path] =
            random_node(root, [](const json& j) { return j.is_object() && !j.empty(); });
        if (!node || !duplicate.empty()) return "none";
        auto it = node->begin();
        std::advance(it, static_cast<long>(pick(node->size())));
        duplicate = it.key();
        it.value() = "<dup>";
        return "twice " + path + "/" + duplicate;
      }
      case 6: {  // another string
        auto [node, path] = random_node(root, [](const json& j) { return j.is_string(); });
        if (!node) return "none";
        const std::string values[] = {"",
                                      "../../../../../../etc/passwd",
                                      "/etc/passwd",
                                      std::string(3000, 'a'),
                                      "model.json",
                                      "zatsiorsky-66kg",
                                      "ZYX",
                                      "root",
                                      "saltus-motion/1",
                                      "caf\xC3\xA9"};
        *node = values[pick(std::size(values))];
        return path + " = string";
      }
      case 7: {  // a quaternion (or any 4-vector) off unit norm, zero, or negated
        auto [node, path] = random_node(
            root, [](const json& j) { return j.is_array() && j.size() == 4 && j[0].is_number(); });
        if (!node) return "none";
        const double factor[] = {1.0005, 1.5, 0.0, -1.0, 1e-9};
        const double f = factor[pick(std::size(factor))];
        for (auto& c : *node)
          c = c.get<double>() * f;
        return path + " *= " + std::to_string(f);
      }
      default: {  // a stored spline's knot
        if (!root.contains("spline") || !root["spline"].is_object() ||
            !root["spline"].contains("knots") || !root["spline"]["knots"].is_array() ||
            root["spline"]["knots"].empty())
          return "none";
        json& knots = root["spline"]["knots"];
        const std::size_t i = pick(knots.size());
        const double values[] = {1e-320, 0.0, -1.0, 4.0, knots[i].get<double>() * 1.01};
        knots[i] = values[pick(std::size(values))];
        return "/spline/knots/" + std::to_string(i) + " = " + knots[i].dump();
      }
    }
  }

  std::string mutate_text(std::string& text) {
    switch (pick(4)) {
      case 0:
        text.resize(pick(text.size()));
        return "truncated";
      case 1:
        text.insert(pick(text.size()), 1, static_cast<char>(0x80 + pick(0x80)));
        return "a byte >= 0x80 inserted";
      case 2: {
        const std::size_t at = text.find_first_of("0123456789", pick(text.size()));
        if (at == std::string::npos) return "none";
        text.insert(at, "1e400");
        return "1e400 inserted";
      }
      default: {
        const std::size_t at = text.find_first_of("0123456789", pick(text.size()));
        if (at == std::string::npos) return "none";
        text.replace(at, 1, "NaN");
        return "NaN inserted";
      }
    }
  }

  std::mt19937_64 rng_;
};

/// Every number in result.json finite (NaN is written as null: only the fields documented as
/// null for this verb may be) and no nan/inf in the CSV's rows.
std::string non_finite_output(const fs::path& out) {
  std::ifstream csv(out / "trajectory.csv");
  std::string line;
  std::getline(csv, line);  // the header names segments, which may contain "inf"
  while (std::getline(csv, line))
    if (line.find("nan") != std::string::npos || line.find("inf") != std::string::npos)
      return "trajectory.csv: " + line.substr(0, 80);
  const json result = read_json((out / "result.json").string());
  for (const char* key : {"objective", "avg_root_force", "rms_force_N", "rms_moment_Nm",
                          "max_force_N", "max_moment_Nm"})
    if (!result["before"][key].is_number()) return std::string("result.json before/") + key;
  return "";
}

/// A failure message for one mutant run, "" if it behaved.
std::string judge(const test::CliRun& run, const fs::path& dir, const std::string& verb) {
  if (run.status == 0) {
    const std::string bad = non_finite_output(dir / "out");
    if (!bad.empty()) return "exit 0 with a non-finite result: " + bad;
    if (names_in(dir) != std::set<std::string>{"m.motion.json", "model.json", "out"})
      return "left something behind";
    return "";
  }
  if (run.status != 2)
    return verb + " exited with " + std::to_string(run.status) + " (not 0 or 2): " + run.output;
  const bool names_file = run.output.find("m.motion.json") != std::string::npos ||
                          run.output.find("model.json") != std::string::npos;
  const bool names_field = run.output.find(": /") != std::string::npos ||
                           run.output.find("line ") != std::string::npos ||
                           run.output.find("(result.json /") != std::string::npos;
  if (!names_file || !names_field) return "exit 2 without file and field: " + run.output;
  if (std::count(run.output.begin(), run.output.end(), '\n') != 1)
    return "more than one line: " + run.output;
  if (names_in(dir) != std::set<std::string>{"m.motion.json", "model.json"})
    return "exit 2 left something behind";
  return "";
}

struct Source {
  std::string name;
  json motion;
};

TEST(MutationFuzz, EveryMutantExitsZeroWithFiniteResultsOrTwoNamingFileAndField) {
  const char* env = std::getenv("SALTUS_FUZZ_MUTANTS");
  const int per_source = env ? std::atoi(env) : 200;
  const json model = read_json(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");

  std::vector<Source> sources;
  for (const auto& entry : fs::directory_iterator(std::string(SALTUS_EXAMPLES_DIR) + "/motions"))
    if (entry.path().string().find(".motion.json") != std::string::npos)
      sources.push_back({entry.path().filename().string(), read_json(entry.path().string())});
  std::sort(sources.begin(), sources.end(),
            [](const Source& a, const Source& b) { return a.name < b.name; });
  ASSERT_GE(sources.size(), 8u);
  {
    test::TempDir dir;
    const auto run = test::run_cli("optimize " + test::m1_path() + " --out " + (dir / "opt") +
                                   " --max-iter 3 --samples 31 -q");
    ASSERT_TRUE(run.status == 0 || run.status == 3) << run.output;
    sources.push_back({"optimized M1", read_json(dir / "opt/optimized.motion.json")});
  }

  std::mutex mutex;
  std::vector<std::string> failures;
  int runs = 0;
  int accepted = 0;
  const auto work = [&](std::size_t first, std::size_t step) {
    test::TempDir dir;
    for (std::size_t s = first; s < sources.size(); s += step) {
      json motion = sources[s].motion;
      motion["model"] = "model.json";
      Mutator mutator(16000 + s);
      for (int i = 0; i < per_source; ++i) {
        const Mutant mutant = mutator.mutate(motion, model);
        test::write_text(dir / "m.motion.json", mutant.motion);
        test::write_text(dir / "model.json", mutant.model);
        const std::string verb = i % 4 == 3 ? "simulate" : "evaluate";
        const auto run = test::run_cli(verb + " " + (dir / "m.motion.json") + " --out " +
                                       (dir / "out") + " --samples 21 -q");
        std::string failure;
        try {
          failure = judge(run, dir.path(), verb);
        } catch (const std::exception& e) {
          failure = std::string("unreadable output: ") + e.what();
        }
        std::error_code ec;
        fs::remove_all(dir / "out", ec);
        std::lock_guard<std::mutex> guard(mutex);
        ++runs;
        accepted += run.status == 0 ? 1 : 0;
        if (!failure.empty())
          failures.push_back(sources[s].name + " mutant " + std::to_string(i) + " (" +
                             mutant.description + "): " + failure);
      }
    }
  };
  std::thread other(work, 1, 2);
  work(0, 2);
  other.join();
  EXPECT_EQ(runs, per_source * static_cast<int>(sources.size()));
  std::printf("%d mutants: %d accepted with finite results, %d refused (exit 2)\n", runs, accepted,
              runs - accepted);
  // A family that is all refused (or all accepted) would test little.
  EXPECT_GT(accepted, runs / 20);
  EXPECT_GT(runs - accepted, runs / 2);
  for (std::size_t i = 0; i < failures.size() && i < 20; ++i)
    ADD_FAILURE() << failures[i];
  EXPECT_TRUE(failures.empty()) << failures.size() << " of " << runs << " mutants misbehaved";
}

}  // namespace
}  // namespace saltus
