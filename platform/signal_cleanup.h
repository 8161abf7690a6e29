// Removing in-flight temporaries when the process is interrupted. Exports stage their
// files in a folder beside the targets (file_set.h); SIGINT or SIGTERM while they are
// written would leave that folder behind, because a signal's default action runs no
// destructors. The CLI installs handlers that remove every registered temporary (files
// first, then folders) and then die by the same signal, so a caller still sees "killed by
// SIGTERM".
//
// Global by necessity: a signal handler reaches nothing else. The registry is a fixed table
// of path buffers claimed with atomics (no allocation, no locks), so the handler calls only
// unlink(), rmdir(), sigaction() and raise(), all async-signal-safe.
#pragma once

#include <filesystem>

namespace sylva {

// SIGINT, SIGTERM and SIGHUP (each unless it was ignored, as under nohup): remove the
// registered temporaries, then take the default action. Call once, early in main().
// Without it the registry is bookkeeping only (the studio keeps its own handlers).
void install_signal_cleanup();

// One temporary file or folder the handler removes. Register it before creating it, drop
// the registration once it was moved into place or removed. When the table is full (64
// temporaries at once) or the path longer than PATH_MAX, nothing is registered and that
// temporary survives an interrupt.
class TempRegistration {
  public:
    enum class Kind { File, Folder };
    TempRegistration(const std::filesystem::path& path, Kind kind);
    ~TempRegistration();
    TempRegistration(const TempRegistration&) = delete;
    TempRegistration& operator=(const TempRegistration&) = delete;

  private:
    int slot_ = -1;
};

// While one lives, SIGINT/SIGTERM/SIGHUP are held back: the handler only notes the signal
// and the last deferral to end removes the temporaries and re-raises it. A commit's moves
// run under one, so an interrupt never leaves half of the files replaced.
class SignalDeferral {
  public:
    SignalDeferral();
    ~SignalDeferral();
    SignalDeferral(const SignalDeferral&) = delete;
    SignalDeferral& operator=(const SignalDeferral&) = delete;
};

}  // namespace sylva
