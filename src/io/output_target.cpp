#include "output_target.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

namespace wobble {

namespace {

constexpr int max_links = 40;  // as the kernel's own limit on a path's links

// N for the names of this process's open descriptors: /dev/stdout, /dev/stderr, /dev/fd/N,
// /proc/self/fd/N, /proc/thread-self/fd/N and /proc/PID/fd/N with this process's PID. Their
// links point at whatever the descriptor holds (a terminal, a pipe, the file of `> log`);
// following them to that file and renaming over it would cut it from the shell's descriptor.
std::optional<int> descriptor_named(const std::string& path) {
  const std::string normal = std::filesystem::path(path).lexically_normal().string();
  if (normal == "/dev/stdout") return 1;
  if (normal == "/dev/stderr") return 2;
  const std::string own = "/proc/" + std::to_string(getpid()) + "/fd/";
  for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                    std::string("/proc/thread-self/fd/"), own}) {
    if (normal.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string number = normal.substr(prefix.size());
    if (number.empty() || number.size() > 9 ||
        number.find_first_not_of("0123456789") != std::string::npos) {
      return std::nullopt;
    }
    return std::stoi(number);
  }
  return std::nullopt;
}

std::string identity_of(const struct stat& info) {
  return std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
}

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// The target of a link that is not one of the descriptor names, fills `target` by its kind.
std::string resolve_entry(const std::string& path, const struct stat& info, OutputTarget& target) {
  target.path = path;
  target.identity = identity_of(info);
  if (S_ISREG(info.st_mode)) {
    target.kind = OutputTarget::Kind::regular_file;
    return "";
  }
  if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) || S_ISFIFO(info.st_mode)) {
    target.kind = OutputTarget::Kind::in_place;
    target.identity = "";  // written in place, one output after the other: nothing is lost
    if (access(path.c_str(), W_OK) != 0)
      return std::string("cannot be written: ") + strerror(errno);
    return "";
  }
  if (S_ISDIR(info.st_mode)) return "is a folder, expected a file path";
  return "is a socket, expected a file, a device or a FIFO";
}

std::string resolve_descriptor(int descriptor, OutputTarget& target) {
  target.kind = OutputTarget::Kind::descriptor;
  target.descriptor = descriptor;
  const int flags = fcntl(descriptor, F_GETFL);
  if (flags < 0 || (flags & O_ACCMODE) == O_RDONLY) {
    return "names descriptor " + std::to_string(descriptor) + ", which is not open for writing";
  }
  struct stat info {};
  // A terminal or a pipe takes two outputs one after the other; only a file can be clobbered.
  target.identity = fstat(descriptor, &info) == 0 && S_ISREG(info.st_mode) ? identity_of(info) : "";
  return "";
}

}  // namespace

std::string resolve_output(const std::string& path, OutputTarget& target) {
  target = OutputTarget();
  std::string current = path;
  for (int links = 0; links <= max_links; ++links) {
    if (const std::optional<int> descriptor = descriptor_named(current)) {
      return resolve_descriptor(*descriptor, target);
    }
    struct stat info {};
    const bool exists = lstat(current.c_str(), &info) == 0;
    if (exists && S_ISLNK(info.st_mode)) {
      char buffer[4096];
      const ssize_t length = readlink(current.c_str(), buffer, sizeof buffer);
      if (length < 0 || length == static_cast<ssize_t>(sizeof buffer)) {
        return "is a link that cannot be read";
      }
      const std::filesystem::path link_target(std::string(buffer, std::size_t(length)));
      current = link_target.is_absolute()
                    ? link_target.string()
                    : (std::filesystem::path(folder_of(current)) / link_target).string();
      continue;
    }
    if (exists) return resolve_entry(current, info, target);
    if (errno != ENOENT) return std::string("cannot be used: ") + strerror(errno);
    // Nothing there: a new file in a folder that must exist.
    target.kind = OutputTarget::Kind::new_file;
    target.path = current;
    const std::string folder = folder_of(current);
    struct stat folder_info {};
    if (stat(folder.c_str(), &folder_info) != 0 || !S_ISDIR(folder_info.st_mode)) {
      return (current == path ? std::string() : "is a link to '" + current + "', whose ") +
             "folder '" + folder + "' does not exist";
    }
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::canonical(folder, error);
    target.identity = "new " + (error ? folder : canonical.string()) + "/" +
                      std::filesystem::path(current).filename().string();
    return "";
  }
  return "is a link in a chain of more than " + std::to_string(max_links) + " links (a loop?)";
}

std::string shown_output(const std::string& path, const OutputTarget& target) {
  std::string shown = "'" + path + "'";
  if (target.kind != OutputTarget::Kind::descriptor && !target.path.empty() &&
      target.path != path) {
    shown += " (a link to '" + target.path + "')";
  }
  return shown;
}

std::string write_all(int fd, const std::string& contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t written = write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      return std::string("write failed: ") + strerror(errno);
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return "";
}

std::string write_in_place(const OutputTarget& target, const std::string& contents,
                           double fifo_wait_seconds) {
  int fd = -1;
  if (target.kind == OutputTarget::Kind::descriptor) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    fd = target.descriptor;
  } else {
    // Non-blocking, so that a FIFO nobody reads fails (ENXIO) instead of waiting forever; it
    // is tried again for a while, as the reader may be starting beside us.
    const auto give_up =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(fifo_wait_seconds);
    while ((fd = open(target.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK)) < 0) {
      if (errno == EINTR) continue;
      if (errno != ENXIO) return std::string("cannot be opened: ") + strerror(errno);
      if (std::chrono::steady_clock::now() > give_up) {
        return "is a FIFO that nobody read within " +
               std::to_string(static_cast<int>(fifo_wait_seconds)) + " s";
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  }
  std::string failure = write_all(fd, contents);
  if (target.kind != OutputTarget::Kind::descriptor && close(fd) != 0 && failure.empty()) {
    failure = std::string("close failed: ") + strerror(errno);
  }
  return failure;
}

}  // namespace wobble
