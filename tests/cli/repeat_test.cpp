// Every verb safe to repeat (issue 49; docs/safety.md, "Output folders"): each verb that writes,
// run twice into its own output, replaces what it wrote and nothing else; any folder verb
// replaces any other verb's result; no verb replaces a file or folder of the user's, nor a file
// the user protected. The verbs are read from the CLI's own --help, so a new verb or export
// format that is not in the table below fails the first test.

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "saltus/use_cases/motion_exports.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

/// One way a verb writes: its command line with OUT where its output goes.
struct Writer {
  std::string verb;     ///< as --help names it: "evaluate", "analyse what-if", "export gltf", ...
  std::string command;  ///< "OUT" is replaced by the output path
  std::string out;      ///< the output's name: a folder, or a file when it has an extension
  bool replaces_own_file = true;  ///< false for a format with no room for a mark (BVH)
  std::vector<int> success = {0};
  bool folder() const { return fs::path(out).extension().empty(); }
};

/// Verbs that write nothing.
const std::set<std::string> kReadOnlyVerbs = {"model info"};

std::string examples(const std::string& path) {
  return std::string(SALTUS_EXAMPLES_DIR) + path;
}

/// Inputs the writers read, made once: an athlete, a BVH capture, a folder with one motion for
/// `paper`, and two shards of a small convergence study for `study merge`.
class Repeat : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    inputs_ = new test::TempDir();
    const std::string quick = " --max-iter 0 --samples 11 -q";
    convergence_ = "study convergence " + test::m1_path() +
                   " --epsilons 100 --mass-errors 0 --timing-errors 0" + quick;
    ASSERT_EQ(run_cli("model new --height 1.6 --mass 55 --sex female --name small --out " +
                      in("small.model.json") + " -q")
                  .status,
              0);
    ASSERT_EQ(
        run_cli("export " + test::m1_path() + " --format bvh --out " + in("m1.bvh") + " -q").status,
        0);
    fs::create_directories(in("motions"));
    fs::copy_file(test::m1_path(), in("motions/M1.motion.json"));
    for (const char* shard : {"1/2", "2/2"})
      ASSERT_EQ(run_cli(convergence_ + " --shard " + shard + " --out " +
                        in(std::string("shard") + shard[0]))
                    .status,
                0);
    const std::string m1 = test::m1_path() + " ";
    const std::string m2 = examples("/motions/M2-tucked-back-somersault.motion.json ");
    writers_ = {
        {"evaluate", "evaluate " + m1 + "--samples 11 -q --out OUT", "evaluate"},
        {"simulate", "simulate " + m1 + "--samples 11 -q --out OUT", "simulate"},
        {"optimize",
         "optimize " + m1 + "--samples 11 --max-iter 1 -q --out OUT",
         "optimize",
         true,
         {0, 3}},
        {"analyse twist", "analyse twist " + m1 + "--samples 11 -q --out OUT", "twist"},
        {"analyse what-if", "analyse what-if " + m2 + "--open-later 0.05 --samples 11 -q --out OUT",
         "what-if"},
        {"import", "import " + in("m1.bvh") + " -q --out OUT", "import"},
        {"study convergence", convergence_ + " --out OUT", "convergence"},
        {"study convergence --shard", convergence_ + " --shard 1/2 --out OUT", "shard"},
        {"study convergence --emit-slurm", convergence_ + " --shards 2 --out s --emit-slurm OUT",
         "study.sbatch"},
        {"study mass", "study mass " + m1 + quick + " --out OUT", "mass"},
        {"study athletes",
         "study athletes " + m1 + "--models " + in("small.model.json") + quick + " --out OUT",
         "athletes"},
        {"study merge", "study merge " + in("shard1") + " " + in("shard2") + " -q --out OUT",
         "merged"},
        {"paper", "paper " + in("motions") + " --quick" + quick + " --out OUT", "paper"},
        {"model new", "model new --height 1.7 --mass 60 --sex male -q --out OUT", "new.model.json"},
        {"model scale", "model scale zatsiorsky-66kg --height 1.8 --mass 70 -q --out OUT",
         "scaled.model.json"},
        {"model yeadon", "model yeadon " + examples("/athletes/yeadon-male1.txt") + " -q --out OUT",
         "yeadon.model.json"},
    };
    for (const ExportFormat& format : export_formats()) {
      const std::string name = "export." + format.name + format.extension;
      writers_.push_back(
          {"export " + format.name, "export " + m1 + "--format " + format.name + " -q --out OUT",
           format.extension.empty() ? "export-" + format.name : name, format.name != "bvh"});
    }
  }
  static void TearDownTestSuite() {
    delete inputs_;
    inputs_ = nullptr;
  }
  static std::string in(const std::string& name) { return *inputs_ / name; }

  /// Runs `w` into `out`.
  static test::CliRun run(const Writer& w, const std::string& out) {
    std::string command = w.command;
    command.replace(command.find("OUT"), 3, "'" + out + "'");
    return run_cli(command);
  }

  static test::TempDir* inputs_;
  static std::string convergence_;
  static std::vector<Writer> writers_;
};

test::TempDir* Repeat::inputs_ = nullptr;
std::string Repeat::convergence_;
std::vector<Writer> Repeat::writers_;

/// Every entry under `root` (relative paths, hidden ones included), and for each file its size.
std::map<std::string, std::uintmax_t> tree(const fs::path& root) {
  std::map<std::string, std::uintmax_t> found;
  if (fs::is_regular_file(root)) return {{"", fs::file_size(root)}};
  for (const auto& e : fs::recursive_directory_iterator(root))
    found[fs::relative(e.path(), root).string()] = e.is_regular_file() ? 1 : 0;
  return found;
}

ino_t inode_of(const fs::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 ? info.st_ino : 0;
}

/// The sub-commands a --help text lists under "Subcommands:".
std::vector<std::string> subcommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream lines(help.substr(std::min(help.size(), help.find("Subcommands:"))));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    if (line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;
    names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

TEST_F(Repeat, EveryVerbThatWritesIsInTheTable) {
  std::set<std::string> verbs;
  for (const Writer& w : writers_)
    verbs.insert(w.verb);
  std::vector<std::string> found;
  for (const std::string& verb : subcommands(run_cli("--help").output)) {
    const std::vector<std::string> inner = subcommands(run_cli(verb + " --help").output);
    if (inner.empty()) found.push_back(verb);
    for (const std::string& sub : inner)
      found.push_back(verb + " " + sub);
  }
  ASSERT_GE(found.size(), 12u) << "the --help texts no longer list the verbs as this test reads";
  for (const std::string& verb : found) {
    if (verb == "export") continue;  // one entry per format, checked below
    EXPECT_TRUE(verbs.count(verb) || kReadOnlyVerbs.count(verb))
        << "`saltus " << verb << "` is not in this test: add how it writes to the table";
  }
  for (const ExportFormat& format : export_formats())
    EXPECT_TRUE(verbs.count("export " + format.name)) << format.name;
}

TEST_F(Repeat, EveryVerbRunTwiceIntoItsOwnOutputReplacesWhatItWroteAndNothingElse) {
  test::TempDir dir;
  test::write_text(dir / "keep.txt", "the user's\n");
  for (const Writer& w : writers_) {
    SCOPED_TRACE(w.verb);
    const fs::path out = dir.path() / w.out;
    const auto first = run(w, out.string());
    ASSERT_NE(std::count(w.success.begin(), w.success.end(), first.status), 0) << first.output;
    const auto written = tree(out);
    const ino_t before = inode_of(out);
    const std::string bytes = w.folder() ? "" : test::read_text(out.string());
    const auto again = run(w, out.string());
    if (w.replaces_own_file) {
      EXPECT_NE(std::count(w.success.begin(), w.success.end(), again.status), 0) << again.output;
      EXPECT_NE(inode_of(out), before) << "not written again";
    } else {
      // BVH has no room for a mark: Saltus cannot tell its file from a user's and keeps it.
      EXPECT_EQ(again.status, 2) << again.output;
      EXPECT_NE(again.output.find(out.string()), std::string::npos) << again.output;
      EXPECT_EQ(test::read_text(out.string()), bytes);
    }
    EXPECT_EQ(tree(out), written) << "the second run wrote other files";
  }
  std::set<std::string> expected = {"keep.txt", "s.shards"};  // the script's shard folders' parent
  for (const Writer& w : writers_)
    expected.insert(w.out);
  std::set<std::string> present = test::names_in(dir.path());
  present.erase("s.shards");
  expected.erase("s.shards");
  EXPECT_EQ(present, expected) << "no temporary, lock or other file is left beside the outputs";
  EXPECT_EQ(test::read_text(dir / "keep.txt"), "the user's\n");
}

TEST_F(Repeat, TheLongestLegalNameIsWrittenTwiceAndOneByteMoreIsRefusedNamingTheFlag) {
  test::TempDir dir;
  // A name of 255 bytes is legal, but its lock and temporaries (`.NAME.lock`, ...) would not
  // be: Saltus shortens theirs. One writer of each mechanism: folders, marked files, a page.
  for (const std::string verb : {"evaluate", "model new", "export html"}) {
    const Writer& w = *std::find_if(writers_.begin(), writers_.end(),
                                    [&](const Writer& x) { return x.verb == verb; });
    SCOPED_TRACE(w.verb);
    const std::string name = std::string(255 - w.out.size(), 'n') + w.out;
    const fs::path out = dir.path() / name;
    ASSERT_EQ(run(w, out.string()).status, 0);
    const ino_t before = inode_of(out);
    const auto again = run(w, out.string());
    EXPECT_EQ(again.status, 0) << again.output;
    EXPECT_NE(inode_of(out), before) << "not written again";
    EXPECT_EQ(test::names_in(dir.path()), std::set<std::string>{name}) << "nothing left beside";
    fs::remove_all(out);
  }
  // A name no file system takes is refused before any work by every writer, naming its flag.
  for (const Writer& w : writers_) {
    SCOPED_TRACE(w.verb);
    const std::size_t at = w.command.find(" OUT");
    const std::string flag =
        w.command.substr(w.command.rfind(' ', at - 1) + 1, at - 1 - w.command.rfind(' ', at - 1));
    const auto refused = run(w, dir / (std::string(256 - w.out.size(), 'n') + w.out));
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find(flag + ": the name"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("256 bytes long"), std::string::npos) << refused.output;
  }
  EXPECT_TRUE(test::names_in(dir.path()).empty());
}

TEST_F(Repeat, AnyFolderVerbReplacesAnotherVerbsResult) {
  test::TempDir dir;
  std::vector<Writer> folders;
  for (const Writer& w : writers_)
    if (w.folder() && w.verb != "paper") folders.push_back(w);  // paper: written over below
  // Each writes over the result of the one before it in the table.
  const std::string out = dir / "out";
  ASSERT_EQ(run(folders.back(), out).status, 0);
  std::string previous = folders.back().verb;
  for (const Writer& w : folders) {
    SCOPED_TRACE(w.verb + " over " + previous);
    const auto r = run(w, out);
    ASSERT_NE(std::count(w.success.begin(), w.success.end(), r.status), 0) << r.output;
    previous = w.verb;
  }
}

TEST_F(Repeat, NoVerbReplacesAFileOrFolderOfTheUsers) {
  test::TempDir dir;
  for (const Writer& w : writers_) {
    SCOPED_TRACE(w.verb);
    const fs::path out = dir.path() / w.out;
    if (w.folder()) {
      // The user's folder, and a Saltus result the user added a file to.
      fs::create_directories(out);
      test::write_text((out / "notes.txt").string(), "mine\n");
      const auto theirs = run(w, out.string());
      EXPECT_EQ(theirs.status, 2) << theirs.output;
      EXPECT_NE(theirs.output.find("notes.txt"), std::string::npos) << theirs.output;
      EXPECT_EQ(tree(out), (std::map<std::string, std::uintmax_t>{{"notes.txt", 1}}));
    } else {
      test::write_text(out.string(), "mine\n");
      const auto theirs = run(w, out.string());
      EXPECT_EQ(theirs.status, 2) << theirs.output;
      EXPECT_NE(theirs.output.find(out.string()), std::string::npos) << theirs.output;
      EXPECT_EQ(test::read_text(out.string()), "mine\n");
      if (!w.replaces_own_file) continue;
      // Saltus's own file, edited since, is the user's; and one the user made read-only is
      // refused as the system's answer (exit 4).
      fs::remove(out);
      ASSERT_NE(std::count(w.success.begin(), w.success.end(), run(w, out.string()).status), 0);
      fs::permissions(out, fs::perms::owner_read | fs::perms::group_read);
      const std::string written = test::read_text(out.string());
      const auto protected_run = run(w, out.string());
      EXPECT_EQ(protected_run.status, 4) << protected_run.output;
      EXPECT_NE(protected_run.output.find("read-only"), std::string::npos) << protected_run.output;
      EXPECT_EQ(test::read_text(out.string()), written);
      fs::permissions(out, fs::perms::owner_write, fs::perm_options::add);
      if (out.extension() == ".glb") continue;  // marked by its generator alone (docs/safety.md)
      std::string edited = written;
      edited[edited.find('1')] = '2';  // a format tag, a number: the document changes
      test::write_text(out.string(), edited);
      EXPECT_EQ(run(w, out.string()).status, 2) << "replaced a file edited since Saltus wrote it";
      EXPECT_EQ(test::read_text(out.string()), edited);
    }
  }
  std::set<std::string> expected;
  for (const Writer& w : writers_)
    expected.insert(w.out);
  std::set<std::string> present = test::names_in(dir.path());
  present.erase("s.shards");
  EXPECT_EQ(present, expected) << "no temporary or lock is left beside the outputs";
}

TEST_F(Repeat, AModelWriterLeavesAResultFoldersModelAlone) {
  test::TempDir dir;
  const std::string out = dir / "optimized";
  ASSERT_EQ(run_cli("evaluate " + test::m1_path() + " --samples 11 -q --out " + out).status, 0);
  const std::string model = test::read_text(out + "/model.json");
  const auto r =
      run_cli("model new --height 1.5 --mass 45 --sex female -q --out " + out + "/model.json");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(test::read_text(out + "/model.json"), model);
}

/// DIR.partial as a run killed after its first case leaves it: study.json and that case's record
/// (and folder), copied from the complete study `full`.
void make_interrupted(const fs::path& full, const fs::path& partial) {
  fs::create_directories(partial / "cases");
  fs::copy_file(full / "study.json", partial / "study.json");
  fs::copy_file(full / "cases/0000.json", partial / "cases/0000.json");
  const auto record = test::read_json((full / "cases/0000.json").string());
  if (record.contains("folder") && record["folder"].is_string())
    fs::copy(full / record["folder"].get<std::string>(),
             partial / record["folder"].get<std::string>(), fs::copy_options::recursive);
}

TEST_F(Repeat, ResumeKeepsWhatTheUserPutInThePartialFolder) {
  test::TempDir dir;
  ASSERT_EQ(run_cli(convergence_ + " --out " + (dir / "full")).status, 0);
  make_interrupted(dir.path() / "full", dir.path() / "out.partial");
  test::write_text(dir / "out.partial/notes.txt", "mine\n");
  test::write_text(dir / "out.partial/cases/notes.txt", "mine too\n");
  const auto resumed = run_cli(convergence_ + " --resume --out " + (dir / "out"));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  // The first case was not run again; the other was.
  EXPECT_EQ(test::read_text(dir / "out/cases/0000.json"),
            test::read_text(dir / "full/cases/0000.json"));
  EXPECT_EQ(test::names_in(dir.path() / "out/cases"), test::names_in(dir.path() / "full/cases"));
  EXPECT_NE(resumed.output.find("notes.txt"), std::string::npos) << resumed.output;
  EXPECT_EQ(tree(dir.path() / "out.partial"),
            (std::map<std::string, std::uintmax_t>{
                {"cases", 0}, {"cases/notes.txt", 1}, {"notes.txt", 1}}))
      << "only what the study wrote there is removed";
  EXPECT_EQ(test::read_text(dir / "out.partial/cases/notes.txt"), "mine too\n");

  // Without anything of the user's, the partial folder goes.
  make_interrupted(dir.path() / "full", dir.path() / "clean.partial");
  ASSERT_EQ(run_cli(convergence_ + " --resume --out " + (dir / "clean")).status, 0);
  EXPECT_FALSE(fs::exists(dir.path() / "clean.partial"));
}

TEST_F(Repeat, ResumeRefusesToMoveACaseFolderHoldingTheUsersFiles) {
  test::TempDir dir;
  const std::string paper = "paper " + in("motions") + " --quick --max-iter 0 --samples 11 -q";
  ASSERT_EQ(run_cli(paper + " --out " + (dir / "full")).status, 0);
  make_interrupted(dir.path() / "full", dir.path() / "out.partial");
  const auto record = test::read_json(dir / "full/cases/0000.json");
  ASSERT_TRUE(record["folder"].is_string()) << "the paper's first case writes a folder";
  const std::string notes =
      dir / ("out.partial/" + record["folder"].get<std::string>() + "/notes.txt");
  test::write_text(notes, "mine\n");
  const auto before = tree(dir.path() / "out.partial");
  const auto refused = run_cli(paper + " --resume --out " + (dir / "out"));
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("notes.txt"), std::string::npos) << refused.output;
  EXPECT_EQ(tree(dir.path() / "out.partial"), before) << "no case ran";
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  EXPECT_EQ(test::read_text(notes), "mine\n");
}

}  // namespace
}  // namespace saltus
