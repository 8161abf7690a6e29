#include "platform/signal_cleanup.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace sylva {
namespace {

enum State : int { kFree, kClaimed, kFile, kFolder };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};

constexpr int kSlots = 64;
Slot slots[kSlots];

std::atomic<int> deferrals{0};
std::atomic<int> pending_signal{0};

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

static_assert(std::atomic<int>::is_always_lock_free, "the handler needs lock-free atomics");

// Async-signal-safe: files first, so the folders are empty when rmdir() comes.
void remove_temporaries() {
    for (Slot& slot : slots)
        if (slot.state.load() == kFile) ::unlink(slot.path);
    for (Slot& slot : slots)
        if (slot.state.load() == kFolder) ::rmdir(slot.path);
}

[[noreturn]] void die_by(int signal_number) {
    remove_temporaries();
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal_number, &action, nullptr);
    // Inside the handler the signal is blocked until it returns; unblock it so the default
    // action happens here and now.
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signal_number);
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    ::raise(signal_number);
    ::_exit(128 + signal_number);  // not reached: the default action ends the process
}

void on_signal(int signal_number) {
    pending_signal.store(signal_number);
    if (deferrals.load() > 0) return;  // the last SignalDeferral re-raises it
    die_by(signal_number);
}

}  // namespace

void install_signal_cleanup() {
    for (int signal_number : kSignals) {
        struct sigaction old {};
        ::sigaction(signal_number, nullptr, &old);
        if (old.sa_handler == SIG_IGN) continue;
        struct sigaction action {};
        action.sa_handler = on_signal;
        sigemptyset(&action.sa_mask);
        for (int other : kSignals) sigaddset(&action.sa_mask, other);
        ::sigaction(signal_number, &action, nullptr);
    }
}

TempRegistration::TempRegistration(const std::filesystem::path& path, Kind kind) {
    const std::string& text = path.native();
    if (text.size() >= PATH_MAX) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slots[i].state.compare_exchange_strong(expected, kClaimed)) continue;
        std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
        slots[i].state.store(kind == Kind::File ? kFile : kFolder);
        slot_ = i;
        return;
    }
}

TempRegistration::~TempRegistration() {
    if (slot_ >= 0) slots[slot_].state.store(kFree);
}

SignalDeferral::SignalDeferral() {
    deferrals.fetch_add(1);
}

SignalDeferral::~SignalDeferral() {
    // Either the handler saw no deferral and died itself, or we see its signal here.
    if (deferrals.fetch_sub(1) == 1)
        if (const int signal_number = pending_signal.load()) die_by(signal_number);
}

}  // namespace sylva
