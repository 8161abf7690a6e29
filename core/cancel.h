// Cancelling long work: every stage (derivation, turtle, fields, meshing, leaves,
// reduction, export) polls the same kind of flag and throws the same Cancelled, so a caller
// catches one type whichever stage was running.
#pragma once

#include <atomic>
#include <stdexcept>

namespace sylva {

// Null: the work cannot be cancelled.
using CancelFlag = const std::atomic<bool>*;

struct Cancelled : std::runtime_error {
    Cancelled() : std::runtime_error("cancelled") {}
};

inline bool is_cancelled(CancelFlag cancel) {
    return cancel && cancel->load(std::memory_order_relaxed);
}

inline void throw_if_cancelled(CancelFlag cancel) {
    if (is_cancelled(cancel)) throw Cancelled();
}

}  // namespace sylva
