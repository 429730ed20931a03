#include "solvers/run/StopSignals.hpp"

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <csignal>
#include <mutex>
#include <thread>

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

namespace glossa::solvers {

namespace {
std::atomic<int> received{0};
std::atomic<std::int64_t> receivedAt{0}; // CLOCK_MONOTONIC nanoseconds of the first signal
// `timeout`, a terminal's Ctrl-C and a batch system signal both the process and its group, so
// one request may arrive twice at once: the same signal again within this window is that one.
constexpr std::int64_t kRepeatWindowNs = 2'000'000'000;

std::int64_t monotonicNs() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now); // async-signal-safe
  return std::int64_t(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}
int wakeFd[2] = {-1, -1};
std::mutex callbackMutex;
std::function<void(int)> callback;

extern "C" void handleStop(int signal) {
  const std::int64_t now = monotonicNs();
  int expected = 0;
  if (!received.compare_exchange_strong(expected, signal)) {
    if (expected == signal && now - receivedAt.load() < kRepeatWindowNs) return;
    // A second signal: the user insists. Die as the default action would.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  receivedAt.store(now);
  const unsigned char byte = static_cast<unsigned char>(signal);
  [[maybe_unused]] const ssize_t n = ::write(wakeFd[1], &byte, 1); // async-signal-safe
}

void watch() {
  unsigned char byte = 0;
  while (true) {
    const ssize_t n = ::read(wakeFd[0], &byte, 1);
    if (n == 1) {
      std::lock_guard<std::mutex> lock(callbackMutex);
      if (callback) callback(static_cast<int>(byte));
    } else if (n == 0 || errno != EINTR)
      return;
  }
}
} // namespace

void installStopSignalHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (::pipe(wakeFd) != 0) return; // no watcher: signals keep their default action
    ::fcntl(wakeFd[1], F_SETFL, O_NONBLOCK); // a handler never blocks on a full pipe
    std::thread(watch).detach();
    struct sigaction action {};
    action.sa_handler = handleStop;
    // Neither handler interrupts the other: the first signal's time is stored before a second is seen.
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGTERM);
    sigaddset(&action.sa_mask, SIGINT);
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
  });
}

int stopSignal() { return received.load(); }

const char *signalName(int signal) {
  switch (signal) {
  case SIGTERM: return "SIGTERM";
  case SIGINT: return "SIGINT";
  default: return "a signal";
  }
}

void onStopSignal(std::function<void(int)> newCallback) {
  std::lock_guard<std::mutex> lock(callbackMutex);
  callback = std::move(newCallback);
}

} // namespace glossa::solvers
