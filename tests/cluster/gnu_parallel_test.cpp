// A study's shards run by GNU parallel (the README's recipe, with the local machine as the one
// sshlogin), merged, and compared with the same study run by Saltus alone.

#include <gtest/gtest.h>

#include <filesystem>

#include "cluster/cluster_support.h"
#include "support/study_compare.h"

namespace saltus {
namespace {

TEST(ClusterParallel, ShardsRunByGnuParallelMergeToTheLocalRun) {
  ASSERT_TRUE(test::have_command("parallel"))
      << "GNU parallel missing: bash tools/bootstrap.sh test installs it";
  test::TempDir dir;
  const auto local = test::run_cli(test::cluster_study(dir / "local") + " --jobs 1");
  ASSERT_EQ(local.status, 0) << local.output;
  // `:` is parallel's name for this machine; on a cluster: --sshlogin 2/node1,2/node2.
  const auto run = test::run_command(
      "cd " + dir.path().string() + " && " + test::bounded("parallel") +
      " --will-cite --halt now,fail=1 --sshlogin 2/: " + "--workdir . " + SALTUS_CLI_PATH + " " +
      test::cluster_study("shards/{}") + " --shard {}/4 --resume --jobs 1 ::: 1 2 3 4");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto merged =
      test::run_cli("study merge " + (dir / "shards/1") + " " + (dir / "shards/2") + " " +
                    (dir / "shards/3") + " " + (dir / "shards/4") + " --out " + (dir / "merged"));
  ASSERT_EQ(merged.status, 0) << merged.output;
  std::string differences;
  for (const std::string& d : test::study_folder_differences(dir / "local", dir / "merged"))
    differences += d + "\n";
  EXPECT_EQ(differences, "");
  std::string left;
  for (const std::string& p : test::processes_in(dir.path().string()))
    left += p + "\n";
  EXPECT_EQ(left, "");
}

}  // namespace
}  // namespace saltus
