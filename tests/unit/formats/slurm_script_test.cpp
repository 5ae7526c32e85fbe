// The Slurm job-array script (formats/slurm_script.h) run by bash itself, without Slurm: a
// stand-in `saltus` prints the arguments it receives, so quoting, the shard each task takes and
// the merge command are checked on what a shell really passes, for a seeded family of awkward
// arguments (spaces, quotes, $, backslashes, newlines, globs).

#include "saltus/formats/slurm_script.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

/// A stand-in executable that prints each argument it gets between < and >, then its folder.
std::string fake_saltus(const test::TempDir& dir) {
  const std::string path = dir / "fake saltus";
  test::write_text(path, "#!/bin/bash\nfor a in \"$@\"; do printf '<%s>\\n' \"$a\"; done\npwd\n");
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

std::string expected_lines(const std::vector<std::string>& arguments) {
  std::string out;
  for (const std::string& a : arguments)
    out += "<" + a + ">\n";
  return out;
}

/// Arguments a shell would mangle if they were not quoted right.
std::vector<std::string> awkward_arguments(unsigned seed) {
  const std::vector<std::string> pieces{"a b", "'", "\"", "$HOME", "\\", "*", "\n",   "`id`",
                                        "--x", "!", ";",  "&",     "é",  "~", "{1,2}"};
  std::mt19937 random(seed);
  std::vector<std::string> arguments{"study", "convergence"};
  const int count = 1 + static_cast<int>(random() % 6);
  for (int i = 0; i < count; ++i) {
    std::string a;
    const int length = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < length; ++k)
      a += pieces[random() % pieces.size()];
    arguments.push_back(a);
  }
  return arguments;
}

TEST(SlurmScript, EachTaskRunsItsShardWithTheArgumentsAsGiven) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    test::TempDir dir;
    SlurmArrayScript s;
    s.executable = fake_saltus(dir);
    s.arguments = awkward_arguments(seed);
    s.working_dir = dir / "work 'dir'";
    fs::create_directories(s.working_dir);
    s.out_dir = "out $x";
    s.shards = 3 + static_cast<int>(seed % 5);
    s.cpus_per_task = 2;
    const std::string script = dir / "study.sbatch";
    write_slurm_array_script(script, s);
    EXPECT_NE(fs::status(script).permissions() & fs::perms::owner_exec, fs::perms::none);
    const std::string text = test::read_text(script);
    EXPECT_NE(text.find("#SBATCH --array=1-" + std::to_string(s.shards) + "\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("#SBATCH --cpus-per-task=2\n"), std::string::npos) << text;

    // Slurm runs the script in --chdir with the task's number and CPUs in the environment.
    const int task = 1 + static_cast<int>(seed % s.shards);
    const auto run = test::run_command("cd " + shell_quote(s.working_dir) +
                                       " && SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
                                       " SLURM_CPUS_PER_TASK=3 bash " + shell_quote(script));
    ASSERT_EQ(run.status, 0) << run.output;
    std::vector<std::string> expected = s.arguments;
    for (const std::string& a :
         {std::string("--shard"), std::to_string(task) + "/" + std::to_string(s.shards),
          std::string("--out"), s.out_dir + ".shards/" + std::to_string(task),
          std::string("--resume"), std::string("--jobs"), std::string("3")})
      expected.push_back(a);
    EXPECT_EQ(run.output, expected_lines(expected) + s.working_dir + "\n") << "seed " << seed;
    EXPECT_TRUE(fs::is_directory(fs::path(s.working_dir) / (s.out_dir + ".shards")));

    // Without SLURM_CPUS_PER_TASK the script's own --cpus-per-task; outside Slurm it refuses.
    const auto plain = test::run_command("cd " + shell_quote(s.working_dir) +
                                         " && SLURM_ARRAY_TASK_ID=1 bash " + shell_quote(script));
    EXPECT_NE(plain.output.find("<--jobs>\n<2>\n"), std::string::npos) << plain.output;
    const auto outside = test::run_command("bash " + shell_quote(script));
    EXPECT_NE(outside.status, 0);
    EXPECT_NE(outside.output.find("run this script with sbatch"), std::string::npos)
        << outside.output;

    // The merge command names every shard folder once, in order.
    const auto merge =
        test::run_command("cd " + shell_quote(s.working_dir) + " && " + slurm_merge_command(s));
    std::vector<std::string> merge_arguments{"study", "merge"};
    for (const std::string& folder : slurm_shard_folders(s))
      merge_arguments.push_back(folder);
    merge_arguments.push_back("--out");
    merge_arguments.push_back(s.out_dir);
    EXPECT_EQ(merge.output, expected_lines(merge_arguments) + s.working_dir + "\n");
    ASSERT_EQ(slurm_shard_folders(s).size(), static_cast<std::size_t>(s.shards));
    EXPECT_EQ(slurm_shard_folders(s).back(), "out $x.shards/" + std::to_string(s.shards));
  }
}

TEST(SlurmScript, ReplacesItsOwnScriptButNoOtherFile) {
  test::TempDir dir;
  SlurmArrayScript s;
  s.executable = "/usr/bin/saltus";
  s.arguments = {"paper", "examples/motions"};
  s.working_dir = dir.path().string();
  s.out_dir = "report";
  s.shards = 4;
  const std::string script = dir / "report.sbatch";
  write_slurm_array_script(script, s);
  s.shards = 8;
  write_slurm_array_script(script, s);  // its own: replaced
  EXPECT_NE(test::read_text(script).find("--array=1-8\n"), std::string::npos);

  const std::string mine = dir / "mine.sh";
  test::write_text(mine, "#!/bin/sh\necho mine\n");
  try {
    write_slurm_array_script(mine, s);
    FAIL() << "overwrote a file Saltus did not write";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), mine);
    EXPECT_NE(std::string(e.what()).find("is not a Slurm script Saltus wrote"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(test::read_text(mine), "#!/bin/sh\necho mine\n");
  EXPECT_EQ(test::names_in(dir.path()), (std::set<std::string>{"report.sbatch", "mine.sh"}))
      << "no temporary is left beside the files";
  // Saltus's script edited by hand is the user's now.
  test::write_text(script, test::read_text(script) + "# my note\n");
  EXPECT_THROW(write_slurm_array_script(script, s), InputError);
  EXPECT_NE(test::read_text(script).find("# my note"), std::string::npos);
  fs::create_directories(dir / "folder.sbatch");
  EXPECT_THROW(write_slurm_array_script(dir / "folder.sbatch", s), InputError);
}

TEST(SlurmScript, ShellQuoteSurvivesTheShell) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::string text;
    const int length = static_cast<int>(random() % 12);
    for (int k = 0; k < length; ++k)
      text += static_cast<char>(1 + random() % 126);  // any byte but NUL
    const auto run = test::run_command("printf '%s' " + shell_quote(text));
    ASSERT_EQ(run.status, 0);
    EXPECT_EQ(run.output, text) << "trial " << trial;
  }
}

}  // namespace
}  // namespace saltus
