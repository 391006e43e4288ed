// Ctrl-C (SIGINT) and SIGTERM. install_interrupt_handling() (from main, before any other thread
// starts) blocks both in every thread and takes them in one waiting thread, so that they never
// land in the middle of a driver call. Until defer_interrupts(), an interrupt ends the process at
// once. Afterwards (a render is running: there is something to save) the first interrupt only
// sets interrupt_requested(): the render loop finishes the pass in flight and what was rendered
// is reconstructed and written; a second interrupt ends the process at once.
//
// An interrupt that ends the process first removes the temporary files registered here, so that
// no hidden temporary is left beside an output; the process then dies by the signal (exit status
// 128 + signal number in a shell).
#pragma once
#include <string>
#include <system_error>

namespace gdr {

void install_interrupt_handling();
void defer_interrupts();
bool interrupt_requested();

// Temporary files: registered while they exist. Each call is one step with respect to an
// interrupt (a file is either registered, or renamed or removed, never half of it).
void register_temporary(const std::string& path);
// open(path, flags, mode) for a new temporary file, registered when it succeeds (-1 and errno
// otherwise).
int open_temporary(const std::string& path, int flags, int mode);
// Renames `tmp` to `target` and forgets `tmp`; returns the rename's error.
std::error_code commit_temporary(const std::string& tmp, const std::string& target);
// Removes `tmp` (if it exists) and forgets it.
void discard_temporary(const std::string& tmp);

}  // namespace gdr
