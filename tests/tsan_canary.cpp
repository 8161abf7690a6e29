// A data race on purpose, for the ThreadSanitizer build only: scripts/sanitize runs it and
// fails when TSan does not report it, so the suppressions (tsan_suppressions.txt) and the
// one-thread TBB (tsan_one_tbb_thread.cpp) are known to leave races in Sylva's kind of code
// visible: two threads of our own, each writing one counter from inside a TBB loop.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <thread>

int main() {
    int counter = 0;
    auto count = [&counter] {
        tbb::parallel_for(tbb::blocked_range<int>(0, 1000), [&counter](const auto& range) {
            for (int i = range.begin(); i != range.end(); ++i) counter = counter + 1;
        });
    };
    std::thread a(count), b(count);
    a.join();
    b.join();
    return counter > 0 ? 0 : 1;
}
