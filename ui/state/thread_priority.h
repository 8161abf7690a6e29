// Background work below the UI thread: a worker that calls lower_thread_priority() first
// gets the cores only when the UI thread (and the software rasteriser's threads, under
// llvmpipe) leave them, so a frame, and a typed character with it, never waits for a
// growth job. Threads the worker starts (TBB's pool, when it starts it) inherit it.
//
// Linux: the calling thread's nice value is raised to kBackgroundNice (never lowered);
// elsewhere it does nothing. Thread-safe; acts on the calling thread only.
#pragma once

namespace sylva::studio {

inline constexpr int kBackgroundNice = 8;

void lower_thread_priority();

}  // namespace sylva::studio
