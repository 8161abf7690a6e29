#include "ui/state/thread_priority.h"

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#endif

namespace sylva::studio {

void lower_thread_priority() {
#ifdef __linux__
    // On Linux a nice value belongs to a thread (its id), not the whole process.
    const auto thread = static_cast<id_t>(syscall(SYS_gettid));
    errno = 0;
    const int now = getpriority(PRIO_PROCESS, thread);
    if (errno == 0) setpriority(PRIO_PROCESS, thread, std::max(now, kBackgroundNice));
#endif
}

}  // namespace sylva::studio
