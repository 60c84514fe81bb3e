#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "sim/input_error.h"

namespace wobble {

namespace {

std::string parent_folder(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

void check_output_path(const std::string& path) {
  if (path.empty()) throw InputError("output path is empty");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path + ": is a folder, expected a file path");
  }
  const std::string folder = parent_folder(path);
  if (!std::filesystem::is_directory(folder, error)) {
    throw InputError(path + ": folder '" + folder + "' does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw InputError(path + ": folder '" + folder + "' is not writable");
  }
}

void prepare_output_folder(const std::string& option, const std::string& folder,
                           const std::string& first_file) {
  struct stat info {};
  if (stat(folder.c_str(), &info) == 0) {
    if (!S_ISDIR(info.st_mode)) throw InputError(option + ": '" + folder + "' is not a folder");
  } else if (mkdir(folder.c_str(), 0777) != 0) {
    throw InputError(option + ": cannot create the folder '" + folder + "' (" +
                     std::strerror(errno) + ")");
  }
  check_output_path(first_file);
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  const std::string pattern = path + ".tmp-XXXXXX";
  std::vector<char> temporary(pattern.begin(), pattern.end());
  temporary.push_back('\0');
  const int fd = mkstemp(temporary.data());
  if (fd < 0) {
    throw OutputError(path + ": cannot create a temporary file: " + std::strerror(errno));
  }
  const auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    close(fd);
    unlink(temporary.data());
    throw OutputError(path + ": " + what + ": " + reason);
  };
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t written = write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  // mkstemp creates the file 0600; give it the permissions an ordinary new file would get.
  const mode_t mask = umask(0);
  umask(mask);
  if (fchmod(fd, 0666 & ~mask) != 0) fail("chmod failed");
  if (fsync(fd) != 0) fail("fsync failed");
  if (close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    unlink(temporary.data());
    throw OutputError(path + ": close failed: " + reason);
  }
  if (std::rename(temporary.data(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    unlink(temporary.data());
    throw OutputError(path + ": rename failed: " + reason);
  }
}

}  // namespace wobble
