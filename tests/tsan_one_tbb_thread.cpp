// Linked into the test executables of the ThreadSanitizer build (SYLVA_TSAN) only.
// Debian's oneTBB is not built with ThreadSanitizer, which therefore cannot see how TBB
// hands a task from one thread to another and reports every hand-off as a data race
// (google/sanitizers#1004). With one thread allowed, TBB runs each task on the thread that
// asked for it, and TSan checks what Sylva synchronizes itself: the studio's jobs, the
// forest preview, progress and cancel across threads.
#include <tbb/global_control.h>

namespace {

const tbb::global_control one_tbb_thread(tbb::global_control::max_allowed_parallelism, 1);

}  // namespace
