// SPDX-License-Identifier: MIT
// Interrupts (rastrules/io/interrupt.hpp). The handler touches only what was prepared before:
// fixed slots of path bytes published by an atomic flag, an atomic process group.
// Implements: SCENE.INPUT.ERRORS (interrupts)
#include "rastrules/io/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace rastrules::io {
namespace {

constexpr std::size_t kSlots = 16;
constexpr std::size_t kPathBytes = 4096;

// A slot is free (0), being written (1) or published (2): the handler reads published ones.
struct Slot {
  std::atomic<int> state{0};
  std::array<char, kPathBytes> path{};
};

std::array<Slot, kSlots> g_slots;
std::atomic<pid_t> g_driver_group{0};
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_mode{static_cast<int>(OnInterrupt::kExit)};
std::atomic<bool> g_installed{false};

extern "C" void on_interrupt(int) {
  g_interrupted.store(true);
  if (const pid_t group = g_driver_group.load(); group > 0)
    ::kill(-group, SIGKILL);
  if (g_mode.load() != static_cast<int>(OnInterrupt::kExit))
    return;
  for (Slot& s : g_slots) {
    if (s.state.load() == 2)
      ::unlink(s.path.data());
  }
  static constexpr char kMessage[] = "rastrules: error: interrupted\n";
  [[maybe_unused]] const ssize_t w = ::write(2, kMessage, sizeof kMessage - 1);
  ::_exit(kExitInterrupted);
}

// SIGBUS: a mapped scene file (open_scene_file) truncated by another process while it is read.
// Nothing can go on after it: the temporaries are removed and the process exits as on bad input.
extern "C" void on_bus_error(int) {
  if (const pid_t group = g_driver_group.load(); group > 0)
    ::kill(-group, SIGKILL);
  for (Slot& s : g_slots) {
    if (s.state.load() == 2)
      ::unlink(s.path.data());
  }
  static constexpr char kMessage[] =
      "rastrules: error: the scene file shrank while it was being read\n";
  [[maybe_unused]] const ssize_t w = ::write(2, kMessage, sizeof kMessage - 1);
  ::_exit(kExitTruncatedInput);
}

} // namespace

void handle_interrupts(OnInterrupt mode) {
  g_mode.store(static_cast<int>(mode));
  if (g_installed.exchange(true))
    return;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; // no SA_RESTART: a blocking call returns with EINTR and the loop checks
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  struct sigaction bus {};
  bus.sa_handler = on_bus_error;
  sigemptyset(&bus.sa_mask);
  ::sigaction(SIGBUS, &bus, nullptr);
}

bool interrupted() {
  return g_interrupted.load();
}

int register_temporary(const std::string& path) {
  if (path.size() >= kPathBytes)
    return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    Slot& s = g_slots[i];
    int free = 0;
    if (!s.state.compare_exchange_strong(free, 1))
      continue;
    std::memcpy(s.path.data(), path.c_str(), path.size() + 1);
    s.state.store(2); // published after the bytes (sequentially consistent store)
    return static_cast<int>(i);
  }
  return -1;
}

void forget_temporary(int slot) {
  if (slot >= 0 && static_cast<std::size_t>(slot) < kSlots)
    g_slots[static_cast<std::size_t>(slot)].state.store(0);
}

void set_driver_group(pid_t group) {
  g_driver_group.store(group);
}

} // namespace rastrules::io
