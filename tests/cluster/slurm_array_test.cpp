// A study as a Slurm job array on a real (single-machine, two-node) Slurm: emitted with
// --emit-slurm, submitted, merged, and compared with the same study run locally.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "cluster/cluster_support.h"
#include "support/study_compare.h"

namespace saltus {
namespace {

TEST(ClusterSlurm, AJobArrayOfShardsMergesToTheLocalRun) {
  if (getuid() != 0) GTEST_SKIP() << "a private Slurm needs root (munged, slurmd)";
  for (const char* command : {"munged", "slurmctld", "slurmd", "sbatch"})
    ASSERT_TRUE(test::have_command(command))
        << command << " missing: bash tools/bootstrap.sh test installs slurm-wlm and munge";
  test::TempDir dir;
  const auto local = test::run_cli(test::cluster_study(dir / "local") + " --jobs 2");
  ASSERT_EQ(local.status, 0) << local.output;

  test::LocalSlurm slurm(dir / "slurm", 2);
  ASSERT_TRUE(slurm.started()) << slurm.output();
  const std::string script = dir / "study.sbatch";
  // Emitted and submitted from the test's folder: the tasks run there and Slurm writes their
  // logs (slurm-<job>_<task>.out) there.
  const std::string in_dir = "cd " + dir.path().string() + " && ";
  const auto emitted =
      test::run_command(in_dir + SALTUS_CLI_PATH + " " + test::cluster_study(dir / "array") +
                        " --emit-slurm " + script + " --shards 3 --jobs 1");
  ASSERT_EQ(emitted.status, 0) << emitted.output;
  EXPECT_NE(test::read_text(script).find("#SBATCH --chdir=" + dir.path().string() + "\n"),
            std::string::npos);
  const auto submitted =
      test::run_command(in_dir + slurm.env() + test::bounded("sbatch --wait ") + script);
  ASSERT_EQ(submitted.status, 0) << submitted.output;
  for (int shard = 1; shard <= 3; ++shard)
    EXPECT_TRUE(
        std::filesystem::exists(dir / ("array.shards/" + std::to_string(shard) + "/study.json")))
        << "shard " << shard;
  const auto merged =
      test::run_cli("study merge " + (dir / "array.shards/1") + " " + (dir / "array.shards/2") +
                    " " + (dir / "array.shards/3") + " --out " + (dir / "array"));
  ASSERT_EQ(merged.status, 0) << merged.output;
  std::string differences;
  for (const std::string& d : test::study_folder_differences(dir / "local", dir / "array"))
    differences += d + "\n";
  EXPECT_EQ(differences, "");

  // A rerun of the array (a requeue) finds every shard complete and runs nothing.
  std::vector<std::filesystem::file_time_type> written;
  for (int shard = 1; shard <= 3; ++shard)
    written.push_back(std::filesystem::last_write_time(
        dir / ("array.shards/" + std::to_string(shard) + "/result.json")));
  const auto again =
      test::run_command(in_dir + slurm.env() + test::bounded("sbatch --wait ") + script);
  EXPECT_EQ(again.status, 0) << again.output;
  for (int shard = 1; shard <= 3; ++shard)
    EXPECT_EQ(std::filesystem::last_write_time(
                  dir / ("array.shards/" + std::to_string(shard) + "/result.json")),
              written[shard - 1])
        << "shard " << shard << " ran again";

  // Nothing is left running: daemons, job steps, the watcher.
  EXPECT_TRUE(slurm.stop()) << "a Slurm daemon is still running";
  std::string left;
  for (const std::string& p : test::processes_in(dir.path().string()))
    left += p + "\n";
  EXPECT_EQ(left, "");
}

}  // namespace
}  // namespace saltus
