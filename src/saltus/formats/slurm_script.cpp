#include "saltus/formats/slurm_script.h"

#include <sstream>

#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

/// The script's format tag, its second line (what may be replaced is told by the last line,
/// slurm_script_kind()).
constexpr const char* kMarker = "# saltus-slurm-array/1";

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

std::vector<std::string> slurm_shard_folders(const SlurmArrayScript& script) {
  std::vector<std::string> folders;
  for (int i = 1; i <= script.shards; ++i)
    folders.push_back(script.out_dir + ".shards/" + std::to_string(i));
  return folders;
}

std::string slurm_merge_command(const SlurmArrayScript& script) {
  std::string command = shell_quote(script.executable) + " study merge";
  for (const std::string& folder : slurm_shard_folders(script))
    command += " " + shell_quote(folder);
  return command + " --out " + shell_quote(script.out_dir);
}

std::string slurm_array_script(const SlurmArrayScript& s) {
  std::ostringstream out;
  const std::string n = std::to_string(s.shards);
  std::string command = shell_quote(s.executable);
  for (const std::string& a : s.arguments)
    command += " " + shell_quote(a);
  out << "#!/bin/bash\n"
      << kMarker << "\n"
      << "# A Saltus study as a Slurm job array, written by `saltus … --emit-slurm`.\n"
      << "# Task I runs shard I/" << n << " of the study into " << s.out_dir
      << ".shards/I, resuming\n"
      << "# what an earlier attempt left (a requeued or rerun task does only the missing cases).\n"
      << "#   sbatch THIS_FILE           then, when every task has ended:\n"
      << "#   " << slurm_merge_command(s) << "\n"
      << "# or both at once (the merge names any case that is missing):\n"
      << "#   id=$(sbatch --parsable THIS_FILE) && sbatch --dependency=afterany:$id --wrap "
      << shell_quote(slurm_merge_command(s)) << "\n"
      << "#SBATCH --job-name=saltus-study\n"
      << "#SBATCH --array=1-" << n << "\n"
      << "#SBATCH --cpus-per-task=" << s.cpus_per_task << "\n"
      << "#SBATCH --chdir=" << s.working_dir << "\n"
      << "set -euo pipefail\n"
      << "shard=\"${SLURM_ARRAY_TASK_ID:?run this script with sbatch}\"\n"
      << "mkdir -p " << shell_quote(s.out_dir + ".shards") << "\n"
      << "exec " << command << " --shard \"$shard/" << n << "\" --out "
      << shell_quote(s.out_dir + ".shards/")
      << "\"$shard\" --resume --jobs \"${SLURM_CPUS_PER_TASK:-" << s.cpus_per_task << "}\"\n";
  return out.str();
}

const FileKind& slurm_script_kind() {
  static const FileKind kind = [] {
    FileKind k = FileKind::commented("Slurm script", "#", "");
    k.executable = true;
    return k;
  }();
  return kind;
}

void write_slurm_array_script(const std::string& path, const SlurmArrayScript& script) {
  write_output_file(path, slurm_array_script(script), slurm_script_kind());
}

}  // namespace saltus
