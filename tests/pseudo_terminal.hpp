// Whether this machine can open a pseudo-terminal, for the tests that need one (a command run under
// `script`, a progress line drawn on a terminal). A container or chroot without /dev/pts mounted has
// none: posix_openpt, grantpt/unlockpt or opening the secondary side fails. Those tests skip there,
// saying why, instead of failing on something that is not ffrf's.
#pragma once

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace ffrf::test {

// Empty when a pseudo-terminal can be opened; otherwise what failed and why.
inline std::string pseudo_terminal_unavailable_reason() {
  const int primary = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (primary < 0) return std::string("no pseudo-terminal can be opened here (posix_openpt: ") + std::strerror(errno) + "; is /dev/pts mounted?)";
  std::string reason;
  if (::grantpt(primary) != 0 || ::unlockpt(primary) != 0) {
    reason = std::string("no pseudo-terminal can be set up here (grantpt/unlockpt: ") + std::strerror(errno) + ")";
  } else {
    const char* name = ::ptsname(primary);
    const int secondary = name == nullptr ? -1 : ::open(name, O_RDWR | O_NOCTTY);
    if (secondary < 0) {
      reason = std::string("the pseudo-terminal's secondary side cannot be opened here (") + (name ? name : "ptsname") + ": " +
               std::strerror(errno) + "; is /dev/pts mounted?)";
    } else {
      ::close(secondary);
    }
  }
  ::close(primary);
  return reason;
}

}  // namespace ffrf::test
