#include "rigdesign/studio/launch_page.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <vector>

extern char** environ;

namespace rigdesign::studio {
namespace {

// The one way text reaches the page: characters that mean nothing to HTML, or refused.
std::string html_safe_url(const std::string& url) {
  constexpr std::string_view kAllowed =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-._~:/?=&[]%";
  if (url.find_first_not_of(kAllowed) != std::string::npos)
    throw std::invalid_argument("studio address '" + url +
                                "' holds a character the launch page does not write");
  return url;
}

std::string private_folder() {
  std::string base = "/tmp";
  for (const char* name : {"XDG_RUNTIME_DIR", "TMPDIR"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && value[0] == '/') {
      base = value;
      break;
    }
  }
  std::string folder = base + "/rigdesign-studio.XXXXXX";
  if (::mkdtemp(folder.data()) == nullptr)  // mode 0700, a new name
    throw std::runtime_error("cannot create a private folder in " + base + ": " +
                             std::strerror(errno));
  return folder;
}

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
}

}  // namespace

LaunchPage::LaunchPage(const std::string& url) {
  const std::string address = html_safe_url(url);
  folder_ = private_folder();
  path_ = folder_ + "/open-studio.html";
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        S_IRUSR | S_IWUSR);
  if (fd < 0) {
    const int error = errno;
    ::rmdir(folder_.c_str());
    throw std::runtime_error("cannot create " + path_ + ": " + std::strerror(error));
  }
  // no-referrer: the address with the token is not sent on from the studio's page either.
  const std::string page =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n"
      "<meta name=\"referrer\" content=\"no-referrer\">\n"
      "<meta http-equiv=\"refresh\" content=\"0; url=" +
      address +
      "\">\n"
      "<title>rigdesign studio</title></head>\n"
      "<body><a href=\"" +
      address + "\">Open the rigdesign studio</a></body></html>\n";
  try {
    write_all(fd, page, path_);
  } catch (...) {
    ::close(fd);
    ::unlink(path_.c_str());
    ::rmdir(folder_.c_str());
    throw;
  }
  ::close(fd);
}

LaunchPage::~LaunchPage() {
  ::unlink(path_.c_str());
  ::rmdir(folder_.c_str());
}

std::optional<int> start_program(const std::string& program, const std::string& argument) {
  pid_t child = 0;
  std::string name = program;
  std::string text = argument;
  std::vector<char*> argv = {name.data(), text.data(), nullptr};
  if (::posix_spawnp(&child, name.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    return std::nullopt;
  std::thread([child] {
    int status = 0;
    ::waitpid(child, &status, 0);
  }).detach();
  return static_cast<int>(child);
}

}  // namespace rigdesign::studio
