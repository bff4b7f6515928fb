// SPDX-License-Identifier: MIT
// Interrupts (SIGINT, SIGTERM) of the command line: what a process must undo when it is
// stopped half way. Temporary output files are registered while they exist, the process
// group of the external driver running now while it runs; the handler removes the first and
// kills the second, both with async-signal-safe calls only. Then either the process exits at
// once with status 130 (a render: nothing of it is worth keeping), or it only records the
// interrupt for a campaign to stop after its current case and write what it has.
// Implements: SCENE.INPUT.ERRORS (interrupts)
#pragma once

#include <sys/types.h>

#include <string>

namespace rastrules::io {

// The exit status of an interrupted run (128 + SIGINT, as shells report it).
inline constexpr int kExitInterrupted = 130;

enum class OnInterrupt {
  kExit,   // remove the registered temporaries, kill the driver's group, _exit(130)
  kRecord, // kill the driver's group, then let interrupted() say so
};

// The exit status when a mapped scene file shrinks while it is read (SIGBUS): bad input.
inline constexpr int kExitTruncatedInput = 2;

// Installs the handler for SIGINT and SIGTERM (once per process; a second call changes the
// mode only), and one for SIGBUS, which a mapped scene file (open_scene_file) raises when
// another process truncates it: temporaries removed, the driver's group killed, a one-line
// error and _exit(kExitTruncatedInput).
void handle_interrupts(OnInterrupt mode);

// Whether SIGINT or SIGTERM arrived since handle_interrupts().
[[nodiscard]] bool interrupted();

// Registers a temporary file to remove on an interrupt; returns its slot, or -1 when all slots
// are taken or the path is too long (it is then not removed on an interrupt).
int register_temporary(const std::string& path);
// Forgets slot (from register_temporary; -1 is ignored) once the file is renamed or removed.
void forget_temporary(int slot);

// Names the process group of the external driver running now (0: none).
void set_driver_group(pid_t group);

} // namespace rastrules::io
