// All-or-nothing output folders (formats/output_folder.h): nothing appears until commit, nothing
// is left when there is no commit, an earlier Saltus result is replaced whole, and a folder or
// file that Saltus did not write is never touched. Which folders are Saltus's own (what the record
// of their writer's declaration says, output_kind.h), the lock that lets one run at a time write a
// folder, the clean-up of what dead runs left, and the messages of failed writes (issue 16 items
// 1-3, 6). The CLI-level fault tests are in tests/cli/output_folder_test.cpp.

#include "saltus/formats/output_folder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::names_in;

/// A writer's declaration, as a verb would make it.
const FolderKind kRun{"evaluate", {"result.json", "trajectory.csv", "model.json"}};
/// What a committed folder holds besides the files written: the record of its kind.
const std::string kRecord = kFolderRecordName;

TEST(OutputFolder, PublishesEveryFileAtOnceOnCommit) {
  test::TempDir dir;
  const fs::path target = dir.path() / "new" / "out";  // the parent does not exist yet either
  OutputFolder folder(target.string(), kRun);
  write_text(folder.file("result.json"), "{}\n");
  write_text(folder.file("trajectory.csv"), "t\n0\n");
  EXPECT_FALSE(fs::exists(target));
  folder.commit();
  EXPECT_EQ(names_in(target), (std::set<std::string>{"result.json", "trajectory.csv", kRecord}));
  EXPECT_EQ(test::read_text((target / kRecord).string()), folder_record_text(kRun));
  EXPECT_EQ(test::read_text((target / "trajectory.csv").string()), "t\n0\n");
  EXPECT_EQ(names_in(target.parent_path()), (std::set<std::string>{"out"}));  // no leftovers
  EXPECT_EQ(fs::path(folder.final_path()), fs::absolute(target));
}

TEST(OutputFolder, LeavesNothingWithoutACommit) {
  test::TempDir dir;
  {
    OutputFolder folder(dir / "out", kRun);
    write_text(folder.file("result.json"), "{}\n");
  }
  EXPECT_TRUE(names_in(dir.path()).empty());
}

TEST(OutputFolder, ReplacesAnEarlierResultWhole) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "out");
  // An earlier result of another verb (issue 16: only Saltus's own results are replaced).
  const FolderKind earlier{"simulate", {"result.json", "trajectory.csv"}};
  write_folder_record(dir / "out", earlier);
  test::write_text(dir / "out/result.json",
                   "{\"format\": \"saltus-result/1\", \"status\": \"simulated\"}\n");
  test::write_text(dir / "out/trajectory.csv", "old\n");
  OutputFolder folder(dir / "out", kRun);
  write_text(folder.file("result.json"), "{\"new\": true}\n");
  folder.commit();
  EXPECT_EQ(names_in(dir.path() / "out"), (std::set<std::string>{"result.json", kRecord}));
  EXPECT_EQ(test::read_text(dir / "out/result.json"), "{\"new\": true}\n");
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out"}));
  // An empty folder is taken too.
  fs::create_directories(dir.path() / "empty");
  OutputFolder empty(dir / "empty", kRun);
  empty.commit();
  EXPECT_TRUE(fs::is_directory(dir.path() / "empty"));
}

TEST(OutputFolder, NeverTouchesWhatSaltusDidNotWrite) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "thesis");
  test::write_text(dir / "thesis/chapter1.tex", "precious");
  EXPECT_THROW(OutputFolder(dir / "thesis", kRun), InputError);
  EXPECT_EQ(names_in(dir.path() / "thesis"), (std::set<std::string>{"chapter1.tex"}));
  test::write_text(dir / "notes.txt", "precious");
  EXPECT_THROW(OutputFolder(dir / "notes.txt", kRun), InputError);
  EXPECT_EQ(test::read_text(dir / "notes.txt"), "precious");
  EXPECT_THROW(OutputFolder("", kRun), InputError);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"thesis", "notes.txt"}));
}

TEST(WriteText, WritesTheBytesOrNamesTheFile) {
  test::TempDir dir;
  write_text(dir / "a.txt", std::string("line\n\0tail", 10));
  EXPECT_EQ(fs::file_size(dir.path() / "a.txt"), 10u);
  try {
    write_text(dir / "missing/a.txt", "x");
    FAIL() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "missing/a.txt"), std::string::npos) << e.what();
  }
}

// Hardening (issue 16).
// write_output_file of a kind without a mark (BVH): new files only, nothing left behind.
const FileKind kBvh = FileKind::unmarked("BVH capture");

TEST(WriteOutputFile, WritesANewFileAndNeverReplacesOne) {
  test::TempDir dir;
  const std::string path = dir / "sub/flight.bvh";
  write_output_file(path, "first\n", kBvh);
  EXPECT_EQ(test::read_text(path), "first\n");
  EXPECT_EQ(names_in(dir / "sub"), std::set<std::string>{"flight.bvh"});
  // Saltus cannot tell its own file from a user's thesis: an existing file is never replaced.
  EXPECT_THROW(write_output_file(path, "second\n", kBvh), InputError);
  EXPECT_EQ(test::read_text(path), "first\n");
  const std::string thesis = dir / "thesis.tex";
  test::write_text(thesis, "\\chapter{Mine}\n");
  try {
    write_output_file(thesis, "HIERARCHY\n", kBvh);
    ADD_FAILURE() << "replaced";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::read_text(thesis), "\\chapter{Mine}\n");
  EXPECT_EQ(names_in(dir / "sub"), std::set<std::string>{"flight.bvh"});
}

TEST(WriteOutputFile, FollowsNoPlantedLink) {
  test::TempDir dir;
  const std::string victim = dir / "victim.txt";
  test::write_text(victim, "keep");
  // A link at the output name, even a dangling one, is an existing entry.
  std::filesystem::create_symlink(dir / "nowhere", dir / "dangling.bvh");
  EXPECT_THROW(write_output_file(dir / "dangling.bvh", "x", kBvh), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "nowhere"));
  // Links at the temporary names an earlier version used, and at the next ones this process
  // would pick, are not written through: each temporary is created with O_EXCL | O_NOFOLLOW.
  std::filesystem::create_symlink(victim, dir / ".out.bvh.saltus-tmp");
  write_output_file(dir / "out.bvh", "new", kBvh);
  EXPECT_EQ(test::read_text(dir / "out.bvh"), "new");
  EXPECT_EQ(test::read_text(victim), "keep");
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{".out.bvh.saltus-tmp", "dangling.bvh",
                                                         "out.bvh", "victim.txt"}));
}

TEST(WriteOutputFile, ASystemRefusalIsAnOutputError) {
  test::TempDir dir;
  test::write_text(dir / "plain", "a file, not a folder");
  EXPECT_THROW(write_output_file(dir / "plain/flight.bvh", "x", kBvh), OutputError);
  EXPECT_THROW(write_output_file("", "x", kBvh), InputError);
  EXPECT_EQ(test::read_text(dir / "plain"), "a file, not a folder");
}

TEST(WriteOutputFile, ReplacesItsOwnMarkedFileUnlessTheUserProtectedIt) {
  test::TempDir dir;
  const FileKind page = FileKind::commented("flight page", "<!--", "-->");
  const std::string path = dir / "flight.html";
  write_output_file(path, "<p>first</p>\n", page);
  write_output_file(path, "<p>second</p>\n", page);  // its own, unchanged: replaced
  EXPECT_EQ(test::read_text(path).find("<p>second</p>\n"), 0u);
  // Made read-only by its user: refused as the system's answer (exit 4), left as it was.
  const std::string before = test::read_text(path);
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read);
  try {
    write_output_file(path, "<p>third</p>\n", page);
    ADD_FAILURE() << "replaced a read-only file";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    EXPECT_FALSE(e.busy());
  }
  EXPECT_EQ(test::read_text(path), before);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"flight.html"});
}

TEST(WriteOutputFile, RemovesWhatKilledWritesLeftAndKeepsALiveRunsTemporary) {
  test::TempDir dir;
  // A process that has ended: its pid is free, as after a kill -9 before the rename.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string dead = dir / (".flight.bvh.saltus-tmp-" + std::to_string(child) + "-0");
  const std::string live = dir / (".flight.bvh.saltus-tmp-" + std::to_string(::getppid()) + "-3");
  const std::string other = dir / (".other.bvh.saltus-tmp-" + std::to_string(child) + "-0");
  const std::string mine = dir / (".flight.bvh.saltus-tmp-" + std::to_string(child) + "-0-x");
  for (const std::string& f : {dead, live, other, mine})
    test::write_text(f, "half");
  write_output_file(dir / "flight.bvh", "HIERARCHY\n", kBvh);
  EXPECT_EQ(names_in(dir.path()),
            (std::set<std::string>{"flight.bvh", fs::path(live).filename().string(),
                                   fs::path(other).filename().string(),
                                   fs::path(mine).filename().string()}))
      << "only the dead write's temporary of this file goes";
}

TEST(SiblingName, KeepsANameThatFitsAndShortensALongOneApartFromItsNeighbours) {
  EXPECT_EQ(sibling_name("out", ".", ".lock"), ".out.lock");
  EXPECT_EQ(sibling_name("out", "", ".partial"), "out.partial");
  const std::string a = std::string(254, 'a') + "1";  // 255 bytes: the longest legal name
  const std::string b = std::string(254, 'a') + "2";
  for (const std::size_t suffix : {std::size_t{0}, std::size_t{21}}) {
    const std::string lock = sibling_name(a, ".", ".tmp-", suffix);
    EXPECT_LE(lock.size() + suffix, 255u) << "fits a file name with the run's suffix";
    EXPECT_EQ(lock, sibling_name(a, ".", ".tmp-", suffix)) << "the same name every time";
    EXPECT_NE(lock, sibling_name(b, ".", ".tmp-", suffix)) << "names that differ at the end";
    EXPECT_EQ(lock.rfind(".aaaa", 0), 0u) << lock;
    EXPECT_EQ(lock.substr(lock.size() - 5), ".tmp-");
  }
  // Cut on a character boundary: a UTF-8 name gives a UTF-8 sibling.
  std::string accents;
  while (accents.size() < 254)
    accents += "\u00e9";
  const std::string cut = sibling_name(accents, ".", ".saltus-tmp-", 21);
  EXPECT_TRUE(is_valid_utf8(cut)) << cut;
  EXPECT_LE(cut.size() + 21, 255u);
}

TEST(WriteOutputFile, TheLongestLegalNameIsWrittenAndReplacedAndItsLeftoversFound) {
  test::TempDir dir;
  const FileKind page = FileKind::commented("flight page", "<!--", "-->");
  const std::string name = std::string(250, 'a') + ".html";  // 255 bytes: legal
  const std::string neighbour = std::string(250, 'a') + ".htm_";
  // What a write of this file killed before its rename left, and one of another file whose
  // name differs only in its last byte (its own business).
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string run = std::to_string(child) + "-0";
  const std::string dead = sibling_name(name, ".", ".saltus-tmp-", 21) + run;
  const std::string other = sibling_name(neighbour, ".", ".saltus-tmp-", 21) + run;
  test::write_text(dir / dead, "half");
  test::write_text(dir / other, "half");
  write_output_file(dir / name, "<p>first</p>\n", page);
  write_output_file(dir / name, "<p>second</p>\n", page);  // its own output: replaced
  EXPECT_EQ(test::read_text(dir / name).rfind("<p>second</p>\n", 0), 0u);
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{name, other}));
  const std::string bvh = std::string(251, 'b') + ".bvh";  // unmarked kinds too
  write_output_file(dir / bvh, "HIERARCHY\n", kBvh);
  EXPECT_EQ(test::read_text(dir / bvh), "HIERARCHY\n");
}

TEST(OutputFolder, TheLongestLegalNameIsWrittenTwiceAndWhatADeadRunLeftGoes) {
  test::TempDir dir;
  const std::string name(255, 'd');
  // A run killed while writing: its temporary, recorded in the lock file it left.
  const std::string temporary = sibling_name(name, ".", ".tmp-", 21) + "4242-0";
  fs::create_directories(dir.path() / temporary);
  test::write_text(dir / sibling_name(name, ".", ".lock"), "4242\ntmp " + temporary + "\n");
  for (const char* text : {"{\"run\": 1}", "{\"run\": 2}"}) {
    OutputFolder folder(dir / name, kRun);
    folder.write("result.json", text);
    folder.commit();
  }
  EXPECT_EQ(test::read_text(dir / (name + "/result.json")), "{\"run\": 2}");
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{name});
}

TEST(WriteOutputFile, AndOutputFolderRefuseANameLongerThanAFileSystemTakes) {
  test::TempDir dir;
  const std::string file = dir / (std::string(252, 'e') + ".bvh");  // 256 bytes
  const std::string folder = dir / (std::string(256, 'e') + "/out");
  for (const auto& write : std::vector<std::function<void()>>{
           [&] { write_output_file(file, "HIERARCHY\n", kBvh); }, [&] { OutputFolder(file, kRun); },
           [&] { check_output_folder(folder); }, [&] { OutputFolder(folder, kRun); }}) {
    try {
      write();
      ADD_FAILURE() << "wrote";
    } catch (const InputError& e) {
      EXPECT_NE(e.problem().find("256 bytes long"), std::string::npos) << e.what();
      EXPECT_NE(e.problem().find("at most 255"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(output_name_problem(dir / std::string(255, 'e')), "");
  EXPECT_TRUE(names_in(dir.path()).empty());
}

TEST(WriteOutputFile, AndOutputFolderRefuseANameSaltusCouldNotReadBack) {
  test::TempDir dir;
  const std::string file = dir / "flight\xff.bvh";  // not UTF-8: the readers refuse it
  try {
    write_output_file(file, "HIERARCHY\n", kBvh);
    ADD_FAILURE() << "wrote " << file;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_NE(e.problem().find("UTF-8"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\xff'), std::string::npos) << "raw byte printed";
  }
  EXPECT_THROW(check_output_folder(dir / "run\xc3"), InputError);  // a cut two-byte character
  EXPECT_THROW(OutputFolder(dir / "run\xc3", kRun), InputError);
  EXPECT_TRUE(names_in(dir.path()).empty());
  write_output_file(dir / "flight \u00e9.bvh", "HIERARCHY\n", kBvh);  // UTF-8: written
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"flight \u00e9.bvh"});
}

namespace hardening {

namespace fs = std::filesystem;

/// A folder holding what a writer of `kind` writes, and the record of its declaration.
void make_result(const fs::path& folder, const FolderKind& kind) {
  fs::create_directories(folder);
  for (const std::string& name : kind.files)
    test::write_text((folder / name).string(), "x");
  for (const std::string& images : kind.image_folders) {
    fs::create_directories(folder / images);
    test::write_text((folder / images / "M1_root_force.png").string(), "png");
  }
  for (const std::string& records : kind.record_folders) {
    fs::create_directories(folder / records);
    test::write_text((folder / records / "0007.json").string(), "{}");
  }
  write_folder_record(folder.string(), kind);
}

/// Declarations that exercise each of the rule's clauses: plain files, a folder of images, a
/// folder of case records, sub-folders that are results themselves. (The verbs' own are tested
/// where they write: tests/cli/repeat_test.cpp runs every verb into its own output.)
const std::vector<FolderKind> kClauses = {
    kRun,
    {"study convergence", {"result.json", "convergence.csv", "study.json"}, {}, {"cases"}},
    {"paper", {"result.json", "report.md"}, {"figures"}, {"cases"}, true},
};

TEST(OutputFolder, AFolderIsSaltusAsItsRecordSaysAndAnyOtherEntryMakesItTheUsers) {
  for (const FolderKind& kind : kClauses) {
    test::TempDir dir;
    const fs::path folder = dir.path() / "r";
    make_result(folder, kind);
    if (kind.holds_results) make_result(folder / "M1", kRun);
    EXPECT_EQ(foreign_content(folder.string()), "") << kind.name;
    test::write_text((folder / "thesis.tex").string(), "mine");
    EXPECT_NE(foreign_content(folder.string()).find("thesis.tex"), std::string::npos) << kind.name;
    fs::remove(folder / "thesis.tex");
    fs::create_directories(folder / "src");
    EXPECT_NE(foreign_content(folder.string()), "") << kind.name << ": a sub-folder of the user's";
    fs::remove(folder / "src");
    fs::create_symlink("/etc/passwd", folder / "link");
    EXPECT_NE(foreign_content(folder.string()), "") << kind.name << ": a link";
    fs::remove(folder / "link");
    // A declared name as a folder, not a file, is not what the writer wrote.
    fs::remove(folder / kind.files.front());
    fs::create_directories(folder / kind.files.front());
    EXPECT_NE(foreign_content(folder.string()), "") << kind.name << ": a folder named as a file";
  }
}

TEST(OutputFolder, WhatIsNotASaltusResult) {
  test::TempDir dir;
  const fs::path folder = dir.path() / "f";
  fs::create_directories(folder);
  EXPECT_EQ(foreign_content(folder.string()), "") << "an empty folder holds nothing to lose";
  test::write_text((folder / "result.json").string(), R"({"format": "other-tool/2"})");
  EXPECT_NE(foreign_content(folder.string()).find("no record of what Saltus wrote"),
            std::string::npos);
  // A result of a Saltus that kept no record: its files cannot be told from the user's.
  test::write_text((folder / "result.json").string(),
                   R"({"format": "saltus-result/1", "status": "evaluated"})");
  EXPECT_NE(foreign_content(folder.string()).find("kept no record"), std::string::npos)
      << foreign_content(folder.string());
  // A record that is not Saltus's, or names entries outside the folder.
  for (const char* record :
       {"not json", R"({"format": "saltus-folder/1"})",
        R"({"format": "saltus-folder/1", "kind": "evaluate", "files": ["../thesis.tex"],
            "image_folders": [], "record_folders": [], "holds_results": false})",
        R"({"format": "saltus-folder/1", "kind": "", "files": [], "image_folders": [],
            "record_folders": [], "holds_results": false})"}) {
    test::write_text((folder / kFolderRecordName).string(), record);
    EXPECT_NE(foreign_content(folder.string()).find("not a record Saltus wrote"), std::string::npos)
        << record << ": " << foreign_content(folder.string());
  }
  // The paper report's figures hold images only; its runs must themselves be results.
  const FolderKind& paper = kClauses.back();
  const fs::path report = dir.path() / "report";
  make_result(report, paper);
  test::write_text((report / "figures/notes.txt").string(), "x");
  EXPECT_NE(foreign_content(report.string()).find("figures/"), std::string::npos);
  fs::remove(report / "figures/notes.txt");
  // Its case records' folder holds records only.
  test::write_text((report / "cases/notes.json").string(), "x");
  EXPECT_NE(foreign_content(report.string()).find("cases/"), std::string::npos);
  fs::remove(report / "cases/notes.json");
  EXPECT_EQ(foreign_content(report.string()), "");
  fs::create_directories(report / "M1");
  test::write_text((report / "M1/thesis.tex").string(), "x");
  EXPECT_NE(foreign_content(report.string()).find("M1/"), std::string::npos);
}

TEST(OutputFolder, AWriterThatWritesWhatItDidNotDeclareFailsAtCommitAndChangesNothing) {
  // The declaration and the writer cannot drift apart unseen: the first run of a writer that
  // writes an undeclared file fails (a bug, exit 1), before DIR is touched.
  test::TempDir dir;
  const std::string out = dir / "out";
  OutputFolder folder(out, kRun);
  folder.write("result.json", "{}");
  folder.write("what_if.csv", "t\n");
  try {
    folder.commit();
    ADD_FAILURE() << "committed an undeclared file";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("what_if.csv"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(OutputFolder, CommitsAllOrNothingAndReplacesOnlyItsOwn) {
  test::TempDir dir;
  const std::string out = dir / "out";
  {
    OutputFolder folder(out, kRun);
    folder.write("result.json", R"({"format": "saltus-result/1", "status": "evaluated"})");
    folder.write("trajectory.csv", "t\n0\n");
    EXPECT_FALSE(fs::exists(out)) << "nothing at DIR before commit";
    // Not committed: nothing remains.
  }
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{});
  {
    OutputFolder folder(out, kRun);
    folder.write("result.json", R"({"format": "saltus-result/1", "status": "evaluated"})");
    folder.commit();
  }
  EXPECT_EQ(names_in(out), (std::set<std::string>{"result.json", kRecord}));
  {
    OutputFolder folder(out, kRun);
    folder.write("result.json", R"({"format": "saltus-result/1", "status": "simulated"})");
    folder.write("model.json", "{}");
    folder.commit();
  }
  EXPECT_EQ(names_in(out), (std::set<std::string>{"result.json", "model.json", kRecord}));
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
  test::write_text(out + "/thesis.tex", "mine");
  EXPECT_THROW((OutputFolder{out, kRun}), InputError);
  EXPECT_THROW(check_output_folder(out), InputError);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
  EXPECT_THROW((OutputFolder{out + "/thesis.tex", kRun}), InputError) << "a file";
  EXPECT_THROW((OutputFolder{"/", kRun}), InputError);
}

TEST(OutputFolder, OneWriterAtATime) {
  test::TempDir dir;
  const std::string out = dir / "out";
  OutputFolder first(out, kRun);
  try {
    OutputFolder second(out, kRun);
    ADD_FAILURE() << "two writers of one folder";
  } catch (const OutputError& e) {
    EXPECT_TRUE(e.busy());
    EXPECT_NE(std::string(e.what()).find("another saltus run (pid " + std::to_string(getpid())),
              std::string::npos)
        << e.what();
  }
  first.write("result.json", R"({"format": "saltus-result/1", "status": "evaluated"})");
  first.commit();
  OutputFolder third(out, kRun);  // free again once committed
}

TEST(OutputFolder, RemovesWhatDeadRunsLeftAndRestoresAMovedAwayFolder) {
  test::TempDir dir;
  const fs::path out = dir.path() / "out";
  // A run killed while writing, and one killed while removing the old folder after the swap.
  fs::create_directories(dir.path() / ".out.tmp-4242-0/M1");
  test::write_text((dir.path() / ".out.tmp-4242-0/M1/trajectory.csv").string(), "partial");
  fs::create_directories(dir.path() / ".out.tmp-77-3");
  // Not Saltus's: other names that merely look alike are left alone, and so is a folder with a
  // run's name that no run of Saltus recorded in the lock file (a user's own).
  fs::create_directories(dir.path() / ".out.tmp-backup");
  fs::create_directories(dir.path() / ".outer.tmp-1-1");
  fs::create_directories(dir.path() / ".out.tmp-1-0");
  test::write_text((dir.path() / ".out.tmp-1-0/notes.txt").string(), "mine");
  fs::create_directories(dir.path() / ".out.old-2-0");
  // The rename fallback killed between its renames: DIR missing, the old folder moved away.
  fs::create_directories(dir.path() / ".out.old-4242-1");
  test::write_text((dir.path() / ".out.old-4242-1/result.json").string(),
                   R"({"format": "saltus-result/1", "status": "evaluated"})");
  write_folder_record(dir / ".out.old-4242-1", kRun);
  // What the dead runs recorded before they created those folders.
  test::write_text((dir.path() / ".out.lock").string(),
                   "4242\ntmp .out.tmp-4242-0\nold .out.old-4242-1\ntmp .out.tmp-77-3\n");
  { OutputFolder folder(out.string(), kRun); }  // not committed
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"out", ".out.tmp-backup", ".outer.tmp-1-1",
                                                         ".out.tmp-1-0", ".out.old-2-0"}));
  EXPECT_TRUE(fs::exists(out / "result.json")) << "the old folder is back";
  EXPECT_EQ(test::read_text((dir.path() / ".out.tmp-1-0/notes.txt").string()), "mine");
}

TEST(OutputFolder, AKilledRunsForkedChildrenDoNotKeepItsLock) {
  // A study (the "run" here) forks its case processes while it holds the folder's lock. Killed
  // with SIGKILL, it cannot remove the lock file; a case process still alive must not hold the
  // lock, or the next run would find the folder busy.
  test::TempDir dir;
  const std::string out = dir / "out";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t run = ::fork();
  ASSERT_GE(run, 0);
  if (run == 0) {
    ::close(ready[0]);
    OutputFolder folder(out, kRun);
    // The case process says when it runs: fork's child handlers (which close the copies) have
    // run by then, however late the scheduler starts it on a loaded machine.
    int started[2];
    if (::pipe(started) != 0) _exit(1);
    const pid_t case_process = ::fork();
    if (case_process == 0) {
      const char byte = 1;
      if (::write(started[1], &byte, 1) != 1) _exit(1);
      ::sleep(10);
      _exit(0);
    }
    char byte = 0;
    if (::read(started[0], &byte, 1) != 1) _exit(1);
    if (::write(ready[1], &case_process, sizeof case_process) != sizeof case_process) _exit(1);
    ::pause();
    _exit(0);
  }
  ::close(ready[1]);
  pid_t case_process = -1;
  ASSERT_EQ(::read(ready[0], &case_process, sizeof case_process),
            static_cast<ssize_t>(sizeof case_process));
  ::close(ready[0]);
  ::kill(run, SIGKILL);
  ::waitpid(run, nullptr, 0);
  EXPECT_EQ(::kill(case_process, 0), 0) << "the case process outlives the run";
  EXPECT_NO_THROW(OutputFolder again(out, kRun));
  ::kill(case_process, SIGKILL);
}

TEST(OutputFolder, LeavesAUsersFileWithTheLocksName) {
  test::TempDir dir;
  const std::string out = dir / "out";
  test::write_text(dir / ".out.lock", "my notes\n");
  EXPECT_THROW(OutputFolder folder(out, kRun), InputError);
  EXPECT_EQ(test::read_text(dir / ".out.lock"), "my notes\n");
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{".out.lock"});
}

TEST(OutputFolder, RefusesAReadOnlyFolderBeforeAnyWork) {
  // Mode 555: the swap would work, but the old result could not be removed afterwards (and as
  // root it could, against its owner's wish). Refused by the check the CLI runs before it
  // computes, and by the constructor.
  test::TempDir dir;
  const std::string out = dir / "out";
  {
    OutputFolder first(out, kRun);
    first.write("result.json", R"({"format": "saltus-result/1", "status": "evaluated"})");
    first.commit();
  }
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  EXPECT_THROW(check_output_folder(out), OutputError);
  EXPECT_THROW(OutputFolder again(out, kRun), OutputError);
  fs::permissions(out, fs::perms::owner_write, fs::perm_options::add);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
  EXPECT_EQ(names_in(out), (std::set<std::string>{"result.json", kRecord}));
}

TEST(OutputFolder, FailedWritesNameTheFinalPathAndTheReason) {
  test::TempDir dir;
  const std::string out = dir / "out";
  OutputFolder folder(out, kRun);
  try {
    folder.write("missing-sub-folder/result.json", "{}");
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_FALSE(e.busy());
    EXPECT_NE(message.find("cannot write " + out +
                           "/missing-sub-folder/result.json: No such "
                           "file or directory"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find(".tmp-"), std::string::npos) << message;
  }
  // A nested folder (the paper report's runs) maps through both temporaries.
  OutputFolder inner(folder.file("M1"), kRun);
  try {
    write_text(inner.file("x/y.csv"), "");
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(out + "/M1/x/y.csv"), std::string::npos) << e.what();
  }
}

}  // namespace hardening

}  // namespace
}  // namespace saltus
