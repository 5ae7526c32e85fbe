#include "saltus/formats/output_folder.h"

#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <mutex>

#include "saltus/base/digest.h"
#include "saltus/base/input_error.h"
#include "saltus/base/input_file.h"
#include "saltus/base/json_reader.h"

namespace saltus {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxResultDepth = 4;  ///< paper report/M1/ is 2 deep
/// Room kept for a run's suffix "<pid>-<n>" (two numbers of up to 10 digits and a dash).
constexpr std::size_t kRunSuffixBytes = 21;

std::string system_reason(int error) {
  return std::strerror(error);
}

/// Refuses an output path whose absolute form `target` is not UTF-8 (`given` in the message):
/// Saltus would write it and then refuse to read it back (base/input_file.h), and results record
/// paths in UTF-8 JSON.
void check_readable_name(const fs::path& target, const std::string& given) {
  if (!is_valid_utf8(target.string()))
    throw InputError(given, "",
                     "the path is not valid UTF-8, so Saltus could not read back what it wrote "
                     "there (it reads only UTF-8 file names, which its results record): choose "
                     "another name");
}

/// The absolute, normalised folder a --out argument names. Throws InputError for paths that name
/// no folder ("", "/") or that Saltus could not read back (check_readable_name).
fs::path target_of(const std::string& final_path) {
  if (final_path.empty()) throw InputError("--out", "", "the output folder path is empty");
  std::error_code ec;
  fs::path target = fs::absolute(final_path, ec).lexically_normal();
  if (ec) throw OutputError("cannot resolve " + final_path + ": " + ec.message(), false);
  check_readable_name(target, final_path);
  if (const std::string why = output_name_problem(final_path); !why.empty())
    throw InputError(final_path, "", why);
  if (target.filename().empty()) target = target.parent_path();  // "out/" -> "out"
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(final_path, "", "names no folder Saltus can write a result to");
  return target;
}

/// Up to three names of a list, for a message.
std::string some_names(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < 3; ++i)
    out += (i ? ", " : "") + printable(names[i]);
  if (names.size() > 3) out += " and " + std::to_string(names.size() - 3) + " more";
  return out;
}

/// Whether `folder` holds regular files only, each passing `wanted`.
bool holds_only(const fs::path& folder, const std::function<bool(const fs::path&)>& wanted) {
  std::error_code ec;
  bool only = true;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    only = only && fs::is_regular_file(it->symlink_status(ec)) && wanted(it->path());
  return only && !ec;
}

/// NNNN.json, at least four digits: a study's case record (study_case_file.h).
bool is_case_record_name(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.size() < 9 || file.extension() != ".json") return false;
  return std::all_of(name.begin(), name.end() - 5, [](char c) { return c >= '0' && c <= '9'; });
}

/// Whether `folder`'s result.json carries a Saltus format tag: a result written before Saltus
/// recorded what it writes (kFolderRecordName), for the message.
bool has_saltus_result_tag(const fs::path& folder) {
  try {
    const nlohmann::json result = read_json_file((folder / "result.json").string());
    return result.is_object() && result.contains("format") && result["format"].is_string() &&
           result["format"].get<std::string>().rfind("saltus-", 0) == 0;
  } catch (const InputError&) {
    return false;
  }
}

std::string foreign_content_at(const fs::path& folder, int depth) {
  std::error_code ec;
  // An empty folder holds nothing to lose; inside a result, every sub-folder must be a result.
  if (fs::is_empty(folder, ec) && !ec) return depth == 0 ? "" : "it is empty";
  std::vector<std::string> entries;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    entries.push_back(it->path().filename().string());
  if (ec) return "it cannot be read (" + ec.message() + ")";
  std::sort(entries.begin(), entries.end());
  std::string why_not;
  const FolderKind kind = read_folder_record(folder.string(), why_not);
  if (!why_not.empty()) {
    if (has_saltus_result_tag(folder))
      return "its result.json is Saltus's, but " + why_not +
             ": it is from a Saltus that kept no record (or the record was removed), so Saltus "
             "cannot tell its files from yours";
    std::vector<std::string> shown;
    for (const std::string& name : entries)
      if (name != kFolderRecordName) shown.push_back(name);
    return "it holds " + some_names(shown) + " and " + why_not;
  }
  std::vector<std::string> foreign;
  for (const std::string& name : entries) {
    if (name == kFolderRecordName) continue;
    const fs::path entry = folder / name;
    const fs::file_status status = fs::symlink_status(entry, ec);
    const auto listed = [&](const std::vector<std::string>& names) {
      return std::find(names.begin(), names.end(), name) != names.end();
    };
    if (fs::is_regular_file(status) && listed(kind.files)) continue;
    if (fs::is_directory(status) && listed(kind.image_folders)) {
      if (holds_only(entry, [](const fs::path& f) { return f.extension() == ".png"; })) continue;
      return "its " + printable(name) + "/ holds files other than the PNG figures Saltus writes";
    }
    if (fs::is_directory(status) && listed(kind.record_folders)) {
      if (holds_only(entry, is_case_record_name)) continue;
      return "its " + printable(name) + "/ holds files other than the case records Saltus writes";
    }
    if (fs::is_directory(status) && kind.holds_results && depth < kMaxResultDepth) {
      const std::string inner = foreign_content_at(entry, depth + 1);
      if (inner.empty()) continue;
      return "its sub-folder " + printable(name) + "/ is not a Saltus result: " + inner;
    }
    foreign.push_back(name);
  }
  if (foreign.empty()) return "";
  return "it holds " + some_names(foreign) + ", which Saltus does not write in " +
         with_article(printable(kind.name)) + " result";
}

/// The InputError for a folder Saltus will not replace, with what to do instead.
InputError refusal(const std::string& shown, const std::string& reason) {
  return InputError(shown, "",
                    "not overwriting this folder: " + reason +
                        ". Saltus replaces only its own earlier results. Give an --out folder "
                        "that does not exist yet (it is created) or an empty one, or move these "
                        "files away first");
}

/// Checks the existing target (if any) may be replaced; the path is `shown` in messages.
void check_target(const fs::path& target, const std::string& shown) {
  struct stat info {};
  if (::lstat(target.c_str(), &info) != 0) {
    if (errno == ENOENT) return;
    throw OutputError("cannot inspect " + shown + ": " + system_reason(errno), false);
  }
  if (S_ISLNK(info.st_mode))
    throw InputError(shown, "",
                     "is a symbolic link; give the folder it points to (Saltus replaces folders, "
                     "not links)");
  if (!S_ISDIR(info.st_mode)) throw InputError(shown, "", "exists and is not a folder");
  // The swap would succeed, but the old result, now at the temporary name, could not be
  // removed (and a root run would remove a folder its owner protected).
  if (!(info.st_mode & S_IWUSR))
    throw OutputError(shown +
                          " is read-only (its mode has no write permission), so Saltus does "
                          "not replace it; nothing was written. Make it writable or choose "
                          "another --out",
                      false);
  const std::string reason = foreign_content_at(target, 0);
  if (!reason.empty()) throw refusal(shown, reason);
}

// ---- Interrupt clean-up -----------------------------------------------------------------------
//
// A signal handler may only call async-signal-safe functions, so the folders of the runs in
// progress are kept in fixed buffers and removed with raw system calls (openat, getdents64,
// unlinkat). The state word is set to kEditing while a slot changes, so the handler never reads
// half-written paths.

constexpr int kSlots = 32;
constexpr int kFree = 0;
constexpr int kEditing = 1;
constexpr int kActive = 2;

struct Slot {
  std::atomic<int> state{kFree};
  char temporary[PATH_MAX];
  char target[PATH_MAX];
  char lock[PATH_MAX];
  char moved_away[PATH_MAX];  ///< the old folder while the rename fallback has moved it away
  int lock_fd = -1;           ///< the lock this run holds (-1: none), see close_locks_in_child
};

Slot g_slots[kSlots];
std::mutex g_slots_mutex;

bool copy_path(char* to, const std::string& from) {
  if (from.size() >= PATH_MAX) return false;
  std::memcpy(to, from.c_str(), from.size() + 1);
  return true;
}

int register_slot(const std::string& temporary, const std::string& target, const std::string& lock,
                  int lock_fd = -1) {
  std::lock_guard<std::mutex> guard(g_slots_mutex);
  for (int i = 0; i < kSlots; ++i) {
    Slot& s = g_slots[i];
    if (s.state.load() != kFree) continue;
    s.state.store(kEditing);
    if (!copy_path(s.temporary, temporary) || !copy_path(s.target, target) ||
        !copy_path(s.lock, lock)) {
      s.state.store(kFree);
      return -1;  // no interrupt clean-up; the next run removes what is left
    }
    s.moved_away[0] = '\0';
    s.lock_fd = lock_fd;
    s.state.store(kActive);
    return i;
  }
  return -1;
}

void set_moved_away(int slot, const std::string& path) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> guard(g_slots_mutex);
  Slot& s = g_slots[slot];
  s.state.store(kEditing);
  if (!copy_path(s.moved_away, path)) s.moved_away[0] = '\0';
  s.state.store(kActive);
}

void unregister_slot(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> guard(g_slots_mutex);
  g_slots[slot].state.store(kFree);
}

/// `path` as it will be once its folder is committed: the temporary folder's name replaced by
/// the final one.
std::string display_path(std::string path) {
  std::lock_guard<std::mutex> guard(g_slots_mutex);
  // Nested folders (the paper report's runs) map through each enclosing temporary in turn,
  // innermost (longest) first.
  for (int round = 0; round < kSlots; ++round) {
    const Slot* best = nullptr;
    std::size_t best_length = 0;
    for (const Slot& s : g_slots) {
      if (s.state.load() != kActive) continue;
      const std::size_t n = std::strlen(s.temporary);
      if (n > best_length && path.size() > n && path.compare(0, n, s.temporary) == 0 &&
          path[n] == '/') {
        best = &s;
        best_length = n;
      }
    }
    if (!best) break;
    path = std::string(best->target) + path.substr(best_length);
  }
  return path;
}

/// Removes `name` (relative to directory `parent`, or a path with AT_FDCWD) and everything under
/// it using only async-signal-safe calls.
bool remove_tree_at(int parent, const char* name, int depth) {
  if (::unlinkat(parent, name, 0) == 0) return true;
  if (errno != EISDIR && errno != EPERM) return errno == ENOENT;
  if (depth > 32) return false;
  const int fd = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  alignas(8) char buffer[4096];
  for (int pass = 0; pass < 16; ++pass) {
    bool any = false;
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (long offset = 0; offset < n;) {
        // struct linux_dirent64: u64 ino, s64 off, u16 reclen, u8 type, char name[].
        unsigned short length = 0;
        std::memcpy(&length, buffer + offset + 16, sizeof length);
        const char* entry = buffer + offset + 19;
        offset += length;
        if (entry[0] == '.' && (entry[1] == '\0' || (entry[1] == '.' && entry[2] == '\0')))
          continue;
        any = true;
        remove_tree_at(fd, entry, depth + 1);
      }
    }
    if (!any) break;
  }
  ::close(fd);
  return ::unlinkat(parent, name, AT_REMOVEDIR) == 0;
}

void on_interrupt(int signal_number) {
  const int saved_errno = errno;
  for (Slot& s : g_slots) {
    if (s.state.load() != kActive) continue;
    if (s.moved_away[0] != '\0') {
      struct stat info {};
      if (::lstat(s.target, &info) != 0)
        ::rename(s.moved_away, s.target);  // between the fallback's two renames: put it back
      else
        remove_tree_at(AT_FDCWD, s.moved_away, 0);
    }
    remove_tree_at(AT_FDCWD, s.temporary, 0);
    ::unlink(s.lock);
  }
  errno = saved_errno;
  // End the way the signal would have ended the process (the shell then reports it).
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  ::sigemptyset(&default_action.sa_mask);
  ::sigaction(signal_number, &default_action, nullptr);
  ::raise(signal_number);
}

/// In a child made by fork() without exec (a study's case process, which ends with _exit): closes
/// its inherited copies of the runs' output locks. An flock belongs to the open file, so a copy
/// would keep the lock held after the run that took it died (a study killed with SIGKILL) for as
/// long as its case processes live; without them the folder is free the moment the run ends.
void close_locks_in_child() {
  for (Slot& s : g_slots)
    if (s.state.load() == kActive && s.lock_fd >= 0) {
      ::close(s.lock_fd);
      s.lock_fd = -1;
    }
}

/// Installs on_interrupt for SIGINT, SIGTERM and SIGHUP where they have their default action
/// (a program that handles them itself keeps its handler), and close_locks_in_child.
void install_interrupt_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    ::pthread_atfork(nullptr, nullptr, close_locks_in_child);
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) != 0) continue;
      if ((current.sa_flags & SA_SIGINFO) || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = on_interrupt;
      ::sigemptyset(&action.sa_mask);
      ::sigaction(signal_number, &action, nullptr);
    }
  });
}

// ---- Locks and stale temporaries --------------------------------------------------------------

/// Appends one line to the lock file: the names of the run's temporary folders are recorded
/// there before they are created, so the next run removes only what a run of Saltus made.
void record_in_lock(int fd, const std::string& line) {
  struct stat info {};
  if (fd < 0 || ::fstat(fd, &info) != 0) return;
  const std::string text = line + "\n";
  if (::pwrite(fd, text.data(), text.size(), info.st_size) < 0) {
    // Unrecorded, the temporary is not removed by the next run: left, never lost.
  }
}

/// What a lock file of Saltus holds: its holder's pid on the first line, then one line per
/// temporary folder ("tmp NAME") and per old folder moved away ("old NAME"). Returns false for
/// anything else (a user's own file of that name); `recorded` receives the names.
bool read_lock_record(int fd, std::vector<std::string>& recorded) {
  std::string text(65536, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  if (n < 0 || n == static_cast<ssize_t>(text.size())) return false;
  text.resize(static_cast<std::size_t>(n));
  std::size_t start = 0;
  for (int line = 0; start < text.size(); ++line) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string row = text.substr(start, end - start);
    start = end + 1;
    if (line == 0) {
      if (row.empty() ||
          !std::all_of(row.begin(), row.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return false;
    } else if (row.rfind("tmp ", 0) == 0 || row.rfind("old ", 0) == 0) {
      recorded.push_back(row);
    } else {
      return false;
    }
  }
  return true;
}

/// Takes the lock `.NAME.lock` of a target: an flock, which the kernel drops when the process
/// ends however it ends. The holder removes the file when it is done; a waiter that locked a
/// file removed meanwhile (its inode no longer at the path) tries again.
int acquire_lock(const std::string& lock_path, const std::string& shown,
                 std::vector<std::string>& recorded) {
  for (int attempt = 0; attempt < 64; ++attempt) {
    const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw OutputError("cannot write to the folder that holds " + shown + ": " +
                            system_reason(errno) + " (" + lock_path + ")",
                        false);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      char text[32] = {};
      const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
      ::close(fd);
      if (error == EWOULDBLOCK) {
        std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "";
        pid = pid.substr(0, pid.find('\n'));
        throw OutputError("another saltus run" + (pid.empty() ? "" : " (pid " + pid + ")") +
                              " is writing " + shown +
                              " right now; nothing was written. Wait for it to finish and run "
                              "again, or choose another --out",
                          true);
      }
      throw OutputError("cannot lock " + lock_path + ": " + system_reason(error), false);
    }
    struct stat held {};
    struct stat at_path {};
    if (::fstat(fd, &held) == 0 && ::stat(lock_path.c_str(), &at_path) == 0 &&
        held.st_ino == at_path.st_ino && held.st_dev == at_path.st_dev) {
      recorded.clear();
      if (!S_ISREG(held.st_mode) || (held.st_size > 0 && !read_lock_record(fd, recorded))) {
        ::close(fd);  // a file of the user's that happens to have the name: left as it is
        throw InputError(lock_path, "",
                         "is not a lock file of Saltus's, and Saltus locks " + shown +
                             " with a file of that name: move it away or choose another --out");
      }
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
        // The pid is only for the message of a run that waits; the lock is what counts.
      }
      return fd;
    }
    ::close(fd);  // removed by its previous holder after we opened it
  }
  throw OutputError("cannot take the lock " + lock_path + " (it keeps changing)", true);
}

bool is_run_suffix(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || c == '-'; });
}

/// Removes what runs that died (killed, power lost) left beside `target`: `.NAME.tmp-<pid>-<n>`
/// folders, and puts back a `.NAME.old-<pid>-<n>` the rename fallback had moved away if the
/// target is missing. Called with the target's lock held, so no live run owns any of them: a
/// live run holds the lock from before it creates its temporary until after it removes it.
void remove_stale_temporaries(const fs::path& target, const std::vector<std::string>& recorded) {
  const fs::path parent = target.parent_path();
  const std::string name = target.filename().string();
  const std::string temporary_prefix = sibling_name(name, ".", ".tmp-", kRunSuffixBytes);
  const std::string old_prefix = sibling_name(name, ".", ".old-", kRunSuffixBytes);
  std::error_code ec;
  std::vector<fs::path> temporaries;
  std::vector<fs::path> moved_away;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    const auto was_recorded = [&](const char* tag) {
      return std::find(recorded.begin(), recorded.end(), std::string(tag) + " " + entry) !=
             recorded.end();
    };
    if (entry.compare(0, temporary_prefix.size(), temporary_prefix) == 0 && was_recorded("tmp") &&
        is_run_suffix(entry.substr(temporary_prefix.size())))
      temporaries.push_back(it->path());
    if (entry.compare(0, old_prefix.size(), old_prefix) == 0 && was_recorded("old") &&
        is_run_suffix(entry.substr(old_prefix.size())))
      moved_away.push_back(it->path());
  }
  for (const fs::path& old : moved_away) {
    struct stat info {};
    if (::lstat(target.c_str(), &info) != 0 && errno == ENOENT)
      fs::rename(old, target, ec);
    else
      fs::remove_all(old, ec);
  }
  for (const fs::path& temporary : temporaries)
    fs::remove_all(temporary, ec);
}

bool same_file(const char* a, const char* b) {
  struct stat x {};
  struct stat y {};
  return ::stat(a, &x) == 0 && ::stat(b, &y) == 0 && x.st_dev == y.st_dev && x.st_ino == y.st_ino;
}

std::atomic<unsigned> g_counter{0};

std::string run_suffix() {
  return std::to_string(::getpid()) + "-" + std::to_string(g_counter.fetch_add(1));
}

}  // namespace

std::string sibling_name(const std::string& name, const std::string& lead, const std::string& tag,
                         std::size_t suffix_bytes) {
  const std::size_t fixed = lead.size() + tag.size() + suffix_bytes;
  if (fixed + name.size() <= NAME_MAX) return lead + name + tag;
  const std::string digest = "~" + text_digest(name);
  std::size_t keep = NAME_MAX - std::min<std::size_t>(NAME_MAX, fixed + digest.size());
  // Cut on a character's first byte, so that a UTF-8 name stays UTF-8.
  while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
    --keep;
  return lead + name.substr(0, keep) + digest + tag;
}

std::string output_name_problem(const std::string& path) {
  for (const fs::path& part : fs::path(path)) {
    const std::string name = part.string();
    if (name.size() <= NAME_MAX) continue;
    std::size_t shown = 24;
    while (shown > 0 && (static_cast<unsigned char>(name[shown]) & 0xC0) == 0x80)
      --shown;
    return "the name \"" + name.substr(0, shown) + "...\" in it is " + std::to_string(name.size()) +
           " bytes long, and a file or folder name may have at most " + std::to_string(NAME_MAX) +
           " bytes: choose a shorter one";
  }
  return "";
}

std::string foreign_content(const std::string& folder) {
  return foreign_content_at(fs::path(folder), 0);
}

void check_output_folder(const std::string& final_path) {
  const fs::path target = target_of(final_path);
  check_target(target, target.string());
}

OutputFolder::OutputFolder(std::string final_path, FolderKind kind) : kind_(std::move(kind)) {
  const fs::path target = target_of(final_path);
  final_path_ = target.string();
  const fs::path parent = target.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec)
    throw OutputError("cannot create the folder " + parent.string() + ": " + ec.message(), false);
  install_interrupt_handlers();
  lock_path_ = (parent / sibling_name(target.filename().string(), ".", ".lock")).string();
  std::vector<std::string> recorded;
  lock_fd_ = acquire_lock(lock_path_, final_path_, recorded);
  try {
    remove_stale_temporaries(target, recorded);
    check_target(target, final_path_);
    for (int attempt = 0;; ++attempt) {
      const std::string name =
          sibling_name(target.filename().string(), ".", ".tmp-", kRunSuffixBytes) + run_suffix();
      temporary_path_ = (parent / name).string();
      record_in_lock(lock_fd_, "tmp " + name);
      if (::mkdir(temporary_path_.c_str(), 0755) == 0) break;
      const int error = errno;
      if (error == EEXIST && attempt < 16) continue;
      throw OutputError(
          "cannot create a folder in " + parent.string() + ": " + system_reason(error), false);
    }
    slot_ = register_slot(temporary_path_, final_path_, lock_path_, lock_fd_);
  } catch (...) {
    temporary_path_.clear();
    release();
    throw;
  }
}

OutputFolder::~OutputFolder() {
  if (!committed_ && !temporary_path_.empty()) {
    std::error_code ec;
    fs::remove_all(temporary_path_, ec);
  }
  release();
}

void OutputFolder::release() {
  unregister_slot(slot_);
  slot_ = -1;
  if (lock_fd_ >= 0) {
    ::unlink(lock_path_.c_str());  // while still holding it (see acquire_lock)
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
}

std::string OutputFolder::file(const std::string& name) const {
  return (fs::path(temporary_path_) / name).string();
}

void OutputFolder::write(const std::string& name, const std::string& text) const {
  write_text(file(name), text);
}

void OutputFolder::commit() {
  if (committed_) return;
  // The record of what Saltus wrote, read by the next run of any verb; what the writer wrote
  // must be what it declared, or that run would refuse the folder as the user's.
  write_folder_record(temporary_path_, kind_);
  if (const std::string undeclared = foreign_content_at(temporary_path_, 0); !undeclared.empty())
    throw std::logic_error("the writer of " + kind_.name + " results wrote what its FolderKind " +
                           "does not declare: " + undeclared);
  const fs::path target(final_path_);
  const bool working_in_target = same_file(".", final_path_.c_str());
  bool exchanged = false;
  for (int attempt = 0;; ++attempt) {
    struct stat info {};
    const bool exists = ::lstat(final_path_.c_str(), &info) == 0;
    if (exists) {
      check_target(target, final_path_);  // it may have changed since the run began
      if (::renameat2(AT_FDCWD, temporary_path_.c_str(), AT_FDCWD, final_path_.c_str(),
                      RENAME_EXCHANGE) == 0) {
        exchanged = true;
        break;
      }
      const int error = errno;
      if (error == ENOENT && attempt < 3) continue;  // removed meanwhile
      if (error != EINVAL && error != ENOSYS && error != ENOTSUP)
        throw OutputError(
            "cannot replace " + final_path_ + ": " + system_reason(error) + "; it is unchanged",
            false);
      // Fallback where the file system cannot exchange (some network and FUSE file systems):
      // two renames. A kill between them leaves DIR missing and the old folder at
      // .DIR.old-<pid>-<n>, which the interrupt handler or the next run puts back.
      const std::string old_name =
          sibling_name(target.filename().string(), ".", ".old-", kRunSuffixBytes) + run_suffix();
      const std::string old = (target.parent_path() / old_name).string();
      record_in_lock(lock_fd_, "old " + old_name);
      set_moved_away(slot_, old);
      if (::rename(final_path_.c_str(), old.c_str()) != 0) {
        const int rename_error = errno;
        set_moved_away(slot_, "");
        throw OutputError("cannot replace " + final_path_ + ": " + system_reason(rename_error) +
                              "; it is unchanged",
                          false);
      }
      if (::rename(temporary_path_.c_str(), final_path_.c_str()) != 0) {
        const int rename_error = errno;
        ::rename(old.c_str(), final_path_.c_str());
        set_moved_away(slot_, "");
        throw OutputError("cannot replace " + final_path_ + ": " + system_reason(rename_error) +
                              "; it is unchanged",
                          false);
      }
      set_moved_away(slot_, "");
      committed_ = true;
      std::error_code ec;
      fs::remove_all(old, ec);
      break;
    }
    if (::renameat2(AT_FDCWD, temporary_path_.c_str(), AT_FDCWD, final_path_.c_str(),
                    RENAME_NOREPLACE) == 0)
      break;
    const int error = errno;
    if (error == EEXIST && attempt < 3) continue;  // created meanwhile: check it, exchange
    if ((error == EINVAL || error == ENOSYS || error == ENOTSUP) &&
        ::rename(temporary_path_.c_str(), final_path_.c_str()) == 0)
      break;
    throw OutputError("cannot create " + final_path_ + ": " + system_reason(error), false);
  }
  committed_ = true;
  if (exchanged) {
    // The temporary name now holds the old folder.
    std::error_code ec;
    fs::remove_all(temporary_path_, ec);
  }
  // A process working inside the old folder (--out .) goes on inside the new one.
  if (working_in_target && ::chdir(final_path_.c_str()) != 0) {
  }
  release();
}

void write_folder_record(const std::string& dir, const FolderKind& kind) {
  write_text((fs::path(dir) / kFolderRecordName).string(), folder_record_text(kind));
}

void write_text(const std::string& path, const std::string& text) {
  const auto fail = [&](int error) {
    return OutputError("cannot write " + display_path(path) + ": " + system_reason(error) +
                           "; nothing was changed",
                       false);
  };
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) throw fail(errno);
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      throw fail(error);
    }
    done += static_cast<std::size_t>(n);
  }
  // close() reports late errors (network file systems report a full disk there). No fsync: the
  // promise is about the process ending in any way, not about power cuts (docs/safety.md), and
  // three fsyncs tripled the time of a small `saltus evaluate`.
  if (::close(fd) != 0) throw fail(errno);
}

namespace {

/// Why the existing regular file `path` may not be replaced by a file of `kind`: "" when it is
/// one Saltus wrote (unmarked_reason), else the problem for an InputError.
std::string existing_file_refusal(const std::string& path, const FileKind& kind) {
  std::string text;
  try {
    text = read_input_file(path, kMaxJsonFileBytes, "files Saltus writes");
  } catch (const InputError& e) {
    return "exists and cannot be read to tell whether Saltus wrote it (" + e.problem() +
           "); it is left as it is";
  }
  const std::string why = unmarked_reason(kind, text);
  if (why.empty()) return "";
  return "exists and " + why + "; Saltus replaces only " + with_article(kind.name) +
         " it wrote, unchanged since: give a new file name or move this one away";
}

/// Writes all of `text` to `fd`; false with errno set on failure.
bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// The name of a temporary beside `name` without the run's suffix: `.NAME.saltus-tmp-`
/// (sibling_name: shortened for the longest legal NAMEs).
std::string file_temporary_prefix(const std::string& name) {
  return sibling_name(name, ".", ".saltus-tmp-", kRunSuffixBytes);
}

/// Removes what writes of `target` that died (killed, power lost) left beside it: regular files
/// `.NAME.saltus-tmp-<pid>-<n>` whose process no longer exists. A live run's temporary stays.
void remove_dead_file_temporaries(const fs::path& target) {
  const std::string prefix = file_temporary_prefix(target.filename().string());
  std::error_code ec;
  std::vector<fs::path> dead;
  for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    if (entry.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string suffix = entry.substr(prefix.size());
    const std::size_t dash = suffix.find('-');
    if (!is_run_suffix(suffix) || dash == 0 || dash == std::string::npos ||
        suffix.find('-', dash + 1) != std::string::npos)
      continue;
    const long pid = std::strtol(suffix.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue;
    if (fs::is_regular_file(it->symlink_status(ec))) dead.push_back(it->path());
  }
  for (const fs::path& file : dead)
    fs::remove(file, ec);
}

}  // namespace

std::size_t write_output_file(const std::string& path, const std::string& plain_text,
                              const FileKind& kind) {
  if (path.empty()) throw InputError("--out", "", "the output file path is empty");
  std::error_code ec;
  const fs::path target = fs::absolute(path, ec).lexically_normal();
  if (ec) throw OutputError("cannot resolve " + path + ": " + ec.message(), false);
  if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
    throw InputError(path, "", "names no file Saltus can write");
  check_readable_name(target, path);
  if (const std::string why = output_name_problem(path); !why.empty())
    throw InputError(path, "", why);
  const std::string text = marked_text(kind, plain_text);
  const bool own = kind.mark != FileMark::kNone;
  const std::string never = "exists and " + unmarked_reason(kind, "") +
                            ", so it writes one only where there is none: remove it or choose "
                            "another name";
  // Why the entry now at `target` may not be replaced; "" when there is none or it is Saltus's.
  const auto refusal = [&]() -> std::string {
    struct stat info {};
    if (::lstat(target.c_str(), &info) != 0) return "";
    if (!own) return never;
    if (S_ISLNK(info.st_mode)) return "is a symbolic link; Saltus writes only to a file of its own";
    if (S_ISDIR(info.st_mode)) return "is a folder, not a file Saltus wrote: give a file name";
    if (!S_ISREG(info.st_mode)) return "is not a file Saltus wrote; it is left as it is";
    const std::string why = existing_file_refusal(target.string(), kind);
    // Saltus's own file that the user protected: the system's answer (exit 4), as for a folder.
    if (why.empty() && !(info.st_mode & S_IWUSR))
      throw OutputError(path +
                            " is read-only (its mode has no write permission), so Saltus does not "
                            "replace it; nothing was written. Make it writable or choose another "
                            "name",
                        false);
    return why;
  };
  if (const std::string why = refusal(); !why.empty()) throw InputError(path, "", why);
  const fs::path parent = target.parent_path();
  fs::create_directories(parent, ec);
  if (ec)
    throw OutputError("cannot create the folder " + parent.string() + ": " + ec.message(), false);

  remove_dead_file_temporaries(target);
  install_interrupt_handlers();
  std::string temporary;
  int fd = -1;
  const mode_t mode = kind.executable ? 0755 : 0644;
  for (int attempt = 0; fd < 0; ++attempt) {
    temporary =
        (parent / (file_temporary_prefix(target.filename().string()) + run_suffix())).string();
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
    if (fd < 0 && !(errno == EEXIST && attempt < 16))
      throw OutputError(
          "cannot write " + path + ": " + system_reason(errno) + "; nothing was changed", false);
  }
  const int slot = register_slot(temporary, target.string(), "");
  const auto discard = [&] {
    ::unlink(temporary.c_str());
    unregister_slot(slot);
  };
  const auto fail = [&](int error, const std::string& what) {
    discard();
    return OutputError(what + " " + path + ": " + system_reason(error) + "; nothing was changed",
                       false);
  };
  if (!write_all(fd, text)) {
    const int error = errno;
    ::close(fd);
    throw fail(error, "cannot write");
  }
  if (::close(fd) != 0) throw fail(errno, "cannot write");
  // The entry may have changed while the text was written: asked again. Where there is none,
  // the move must not replace one that appears meanwhile (RENAME_NOREPLACE); where there is one
  // of Saltus's, a plain rename replaces it.
  for (int attempt = 0;; ++attempt) {
    std::string why;
    try {
      why = refusal();
    } catch (const OutputError&) {
      discard();
      throw;
    }
    if (!why.empty()) {
      discard();
      throw InputError(path, "", why);
    }
    struct stat info {};
    if (::lstat(target.c_str(), &info) == 0) {
      if (::rename(temporary.c_str(), target.c_str()) != 0)
        throw fail(errno, "cannot move into place");
      break;
    }
    int error =
        ::renameat2(AT_FDCWD, temporary.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0
            ? 0
            : errno;
    if (error == EINVAL || error == ENOSYS) {
      // No RENAME_NOREPLACE here: a hard link fails as well when the name is taken.
      error = ::link(temporary.c_str(), target.c_str()) == 0 ? 0 : errno;
      if (error == 0) ::unlink(temporary.c_str());
    }
    if (error == 0) break;
    if (error != EEXIST || attempt >= 3) throw fail(error, "cannot move into place");
    // Created meanwhile: the next round asks whether it may be replaced.
  }
  unregister_slot(slot);
  return text.size();
}

}  // namespace saltus
