#pragma once
/// @file
/// A Slurm job array for a study (`saltus study … --emit-slurm FILE --shards N`): array task I
/// runs shard I/N of the same command into OUT.shards/I with --resume (a requeued or rerun
/// task does only the cases it lacks), on --cpus-per-task cases at a time; then
/// `saltus study merge OUT.shards/* --out OUT` writes what one run would have.

#include <string>
#include <vector>

#include "saltus/formats/output_kind.h"

namespace saltus {

struct SlurmArrayScript {
  std::string executable;              ///< absolute path of `saltus`
  std::vector<std::string> arguments;  ///< the study command without its run options
  std::string working_dir;  ///< where the command's relative paths resolve (sbatch --chdir)
  std::string out_dir;      ///< the merged study's folder, as the user gave it
  int shards = 1;
  int cpus_per_task = 1;  ///< cases each array task runs at once (--jobs)
};

/// OUT.shards/1 … OUT.shards/N.
std::vector<std::string> slurm_shard_folders(const SlurmArrayScript& script);

/// The merge command for after the array, shell-quoted.
std::string slurm_merge_command(const SlurmArrayScript& script);

/// The batch script's text.
std::string slurm_array_script(const SlurmArrayScript& script);

/// What the script writer declares (output_kind.h): an executable text file marked by a last
/// comment line, so a script Saltus wrote, unchanged since, is replaced and no other file is.
const FileKind& slurm_script_kind();

/// Writes the script (executable) by the one rule for single files (write_output_file). Throws
/// InputError if `path` exists and is not a script that Saltus wrote, unchanged since.
void write_slurm_array_script(const std::string& path, const SlurmArrayScript& script);

/// `text` quoted for a POSIX shell ('…', with ' as '\'').
std::string shell_quote(const std::string& text);

}  // namespace saltus
