#include "atomic_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/output_target.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

std::string parent_folder(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// The temporary file being written, for the signal handler: a plain buffer and a flag, since a
// handler may touch nothing else.
char pending_temporary[4096 + 64];
volatile std::sig_atomic_t has_pending_temporary = 0;

extern "C" void remove_temporary_and_end(int signal_number) {
  const int saved_errno = errno;
  if (has_pending_temporary) unlink(pending_temporary);
  errno = saved_errno;
  // SA_RESETHAND has put the default action back; the signal is blocked until this returns,
  // then ends the program as it would have without the handler.
  raise(signal_number);
}

// SIGTERM and SIGINT held back on this thread for the lifetime of this object (Wobble's other
// threads, the worker pool's helpers, block every signal), so that a temporary file is
// never made, renamed or removed without the handler knowing.
class TerminationBlocked {
 public:
  TerminationBlocked() {
    sigset_t blocked;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGTERM);
    sigaddset(&blocked, SIGINT);
    pthread_sigmask(SIG_BLOCK, &blocked, &previous_);
  }
  ~TerminationBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  TerminationBlocked(const TerminationBlocked&) = delete;
  TerminationBlocked& operator=(const TerminationBlocked&) = delete;

 private:
  sigset_t previous_;
};

// mkstemp on PATH.tmp-XXXXXX, with the name left for the signal handler. Returns the file
// descriptor (or -1, errno set) and the name in `name`.
int create_temporary(const std::string& path, std::vector<char>& name) {
  const std::string pattern = path + ".tmp-XXXXXX";
  name.assign(pattern.begin(), pattern.end());
  name.push_back('\0');
  const TerminationBlocked blocked;
  const int fd = mkstemp(name.data());
  if (fd >= 0 && name.size() <= sizeof pending_temporary) {
    std::memcpy(pending_temporary, name.data(), name.size());
    has_pending_temporary = 1;
  }
  return fd;
}

// Remove the temporary file (`remove`; not once it was renamed), and forget it.
void forget_temporary(const std::vector<char>& name, bool remove) {
  const TerminationBlocked blocked;
  if (remove) unlink(name.data());
  has_pending_temporary = 0;
}

// fsync the folder holding `path`. Throws OutputError when the disk reports an error; a
// filesystem that cannot sync folders (EINVAL) or a folder that cannot be opened for reading
// (write-only permissions) is left as it is: the file itself was synced before the rename.
void sync_folder(const std::string& path) {
  const std::string folder = parent_folder(path);
  const int fd = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  const int result = fsync(fd);
  const int error = errno;
  close(fd);
  if (result != 0 && error != EINVAL && error != EROFS) {
    throw OutputError(path +
                      ": written, but its folder could not be synced: " + std::strerror(error));
  }
}

}  // namespace

void check_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError(option + ": expected a file path, got ''");
  OutputTarget target;
  const std::string problem = resolve_output(path, target);
  if (!problem.empty()) throw InputError(option + ": '" + path + "' " + problem);
  if (target.kind == OutputTarget::Kind::in_place ||
      target.kind == OutputTarget::Kind::descriptor) {
    return;  // written where it is: nothing is made beside it
  }
  // The very file the write will make first, made and removed: whatever would stop the write
  // at the end of the run stops it now.
  std::vector<char> temporary;
  const int fd = create_temporary(target.path, temporary);
  if (fd < 0) {
    throw InputError(option + ": cannot write a file beside " + shown_output(path, target) + ": " +
                     std::strerror(errno) + ", expected a writable folder and a shorter name");
  }
  close(fd);
  forget_temporary(temporary, true);
}

void check_output_folder(const std::string& option, const std::string& folder,
                         const std::string& first_file) {
  if (folder.empty()) throw InputError(option + ": expected a folder path, got ''");
  struct stat info {};
  if (stat(folder.c_str(), &info) == 0) {
    if (!S_ISDIR(info.st_mode)) throw InputError(option + ": '" + folder + "' is not a folder");
    check_output_path(option, first_file);
    return;
  }
  if (errno != ENOENT) {
    throw InputError(option + ": cannot use the folder '" + folder + "': " + std::strerror(errno));
  }
  // Missing: it must be possible to make it, which only trying tells (long names, read-only
  // disks, folders without write permission), so make it and take it away again.
  if (mkdir(folder.c_str(), 0777) != 0) {
    throw InputError(option + ": cannot create the folder '" + folder + "' (" +
                     std::strerror(errno) + ")");
  }
  rmdir(folder.c_str());
}

void make_output_folder(const std::string& folder) {
  if (mkdir(folder.c_str(), 0777) != 0 && errno != EEXIST) {
    throw OutputError(folder + ": cannot create the folder: " + std::strerror(errno));
  }
}

void write_output_file(const std::string& output, const std::string& contents) {
  // Resolved again at the write: a later frame's name, or a link made since the checks.
  OutputTarget target;
  const std::string problem = resolve_output(output, target);
  if (!problem.empty()) throw OutputError(output + ": " + problem + "; nothing written");
  if (target.kind == OutputTarget::Kind::in_place ||
      target.kind == OutputTarget::Kind::descriptor) {
    const std::string failure = write_in_place(target, contents);
    if (!failure.empty()) throw OutputError(output + ": " + failure);
    return;
  }
  // A link is written through: its target is replaced, the link stays.
  const std::string& path = target.path;
  struct stat info {};
  const bool replaces = stat(path.c_str(), &info) == 0;
  if (replaces && !S_ISREG(info.st_mode)) {
    throw OutputError(output + ": exists and is not a regular file; not replaced");
  }
  std::vector<char> temporary;
  const int fd = create_temporary(path, temporary);
  if (fd < 0) {
    throw OutputError(path + ": cannot create a temporary file: " + std::strerror(errno));
  }
  const auto fail = [&](const std::string& reason) {
    close(fd);
    forget_temporary(temporary, true);
    throw OutputError(path + ": " + reason);
  };
  const std::string write_failure = write_all(fd, contents);
  if (!write_failure.empty()) fail(write_failure);
  // mkstemp creates the file 0600. A replaced file keeps its permissions (a shared 0644 image
  // stays readable by others, a private 0600 one stays private); a new file gets those an
  // ordinary new file would get. Set-user and set-group bits are not carried over.
  mode_t mode = 0;
  if (replaces) {
    mode = info.st_mode & 0777;
  } else {
    const mode_t mask = umask(0);
    umask(mask);
    mode = 0666 & ~mask;
  }
  if (fchmod(fd, mode) != 0) fail(std::string("chmod failed: ") + std::strerror(errno));
  if (fsync(fd) != 0) fail(std::string("fsync failed: ") + std::strerror(errno));
  if (close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    forget_temporary(temporary, true);
    throw OutputError(path + ": close failed: " + reason);
  }
  const TerminationBlocked blocked;  // renamed and forgotten as one
  if (std::rename(temporary.data(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    forget_temporary(temporary, true);
    throw OutputError(path + ": rename failed: " + reason);
  }
  forget_temporary(temporary, false);
  // The rename is only on disk once the folder is: without this, a power cut soon after could
  // leave the old file, or none, in place of the new one.
  sync_folder(path);
}

void remove_temporary_file_on_termination() {
  struct sigaction action {};
  action.sa_handler = remove_temporary_and_end;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  for (const int signal_number : {SIGTERM, SIGINT}) {
    // A signal the parent told us to ignore (nohup, a background shell job) stays ignored.
    struct sigaction current {};
    sigaction(signal_number, nullptr, &current);
    if (current.sa_handler != SIG_IGN) sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace wobble
