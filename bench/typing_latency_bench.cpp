// Typing latency in the studio's rules editor, key to glyph on the screen, while a growth
// job runs: starts `sylva-studio --bench-typing N` (which keeps a growth job running and
// focuses the editor), types N letters as X key events (XTest, as a keyboard does), and
// for each reads the editor's line back from the X server until its pixels change. Prints
// the figures, then the studio's own (key read to frame on screen, the jobs' times).
//
//   xvfb-run -a -s "-screen 0 1280x800x24" build/bench/sylva-bench-typing
//       [--studio build/ui/sylva-studio] [--keys 40] [--template templates/spruce.toml]
//       [--set KEY=VALUE]... [-- STUDIO ARGS]
//
// The default tree is the spruce at crown_resolution 800 and trunk_resolution 360 with no
// triangle budget (meshed at those resolutions): a growth job of about a second on two idle
// cores. `-- --bench-no-job` gives the same figures with nothing growing. --set rewrites a
// [params] line of the template file (a copy in /tmp).
//
// Needs an X display. libXtst is loaded at run time (its headers are not needed to build).
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <dlfcn.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

struct Studio {
    pid_t pid = -1;
    FILE* out = nullptr;  // its stdout
};

Studio start_studio(const std::vector<std::string>& args) {
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0) std::exit(1);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
    posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    Studio studio;
    if (posix_spawn(&studio.pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) {
        std::fprintf(stderr, "sylva-bench-typing: cannot start %s\n", argv[0]);
        std::exit(1);
    }
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_fds[1]);
    studio.out = fdopen(pipe_fds[0], "r");
    return studio;
}

// The next line the studio prints that starts with "typing bench: "; empty at its end.
std::string bench_line(const Studio& studio) {
    char line[1024];
    while (std::fgets(line, sizeof line, studio.out))
        if (std::strncmp(line, "typing bench: ", 14) == 0) return line;
    return {};
}

// The region's pixels as the X server has them now.
std::vector<char> grab(Display* display, Window root, int x, int y, int w, int h) {
    XImage* image = XGetImage(display, root, x, y, static_cast<unsigned>(w),
                              static_cast<unsigned>(h), AllPlanes, ZPixmap);
    if (!image) return {};
    std::vector<char> pixels(image->data,
                             image->data + static_cast<std::ptrdiff_t>(image->bytes_per_line) * h);
    XDestroyImage(image);
    return pixels;
}

// A copy of the template file at `path` with each "KEY=VALUE" as its [params] line.
std::string template_with(const std::string& path, const std::vector<std::string>& sets) {
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "sylva-bench-typing: cannot read %s\n", path.c_str());
        std::exit(2);
    }
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (const std::string& set : sets) {
        const std::size_t eq = set.find('=');
        const std::string key = set.substr(0, eq), value = set.substr(eq + 1);
        std::erase_if(lines, [&key](const std::string& line) {
            return line.rfind(key + " ", 0) == 0 || line.rfind(key + "=", 0) == 0;
        });
        auto params = std::find(lines.begin(), lines.end(), "[params]");
        if (params == lines.end()) params = lines.insert(lines.end(), "[params]");
        lines.insert(params + 1, key + " = " + value);
    }
    const std::string out = "/tmp/sylva-bench-typing-" + std::to_string(getpid()) + ".toml";
    std::ofstream file(out);
    for (const std::string& line : lines) file << line << "\n";
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string studio_path = "build/ui/sylva-studio", tree = "templates/spruce.toml";
    int keys = 40;
    std::vector<std::string> extra, sets;
    bool sets_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--studio" && i + 1 < argc)
            studio_path = argv[++i];
        else if (arg == "--keys" && i + 1 < argc)
            keys = std::max(std::atoi(argv[++i]), 1);
        else if (arg == "--template" && i + 1 < argc)
            tree = argv[++i];
        else if (arg == "--set" && i + 1 < argc && std::strchr(argv[i + 1], '='))
            sets.push_back(argv[++i]), sets_given = true;
        else if (arg == "--")
            extra.assign(argv + i + 1, argv + argc), i = argc;
        else {
            std::fprintf(stderr,
                         "usage: sylva-bench-typing [--studio PATH] [--keys N] [--template FILE] "
                         "[--set KEY=VALUE]... [-- STUDIO ARGS]\n");
            return 2;
        }
    }
    Display* display = XOpenDisplay(nullptr);
    if (!display) {
        std::fprintf(stderr, "sylva-bench-typing: no X display (run it under xvfb-run -a)\n");
        return 1;
    }
    void* xtst = dlopen("libXtst.so.6", RTLD_NOW);
    using FakeKey = int (*)(Display*, unsigned, int, unsigned long);
    FakeKey fake_key = xtst ? reinterpret_cast<FakeKey>(dlsym(xtst, "XTestFakeKeyEvent")) : nullptr;
    if (!fake_key) {
        std::fprintf(stderr, "sylva-bench-typing: libXtst.so.6 is missing\n");
        return 1;
    }

    if (!sets_given && tree == "templates/spruce.toml")
        sets = {"crown_resolution=800", "trunk_resolution=360", "triangle_budget=0"};
    const std::string file = template_with(tree, sets);
    std::printf("growing %s with %zu change(s) in a loop, typing %d keys\n", tree.c_str(),
                sets.size(), keys);
    std::vector<std::string> args = {studio_path, "--template", file, "--bench-typing",
                                     std::to_string(keys)};
    args.insert(args.end(), extra.begin(), extra.end());
    Studio studio = start_studio(args);
    const std::string ready = bench_line(studio);
    int x = 0, y = 0, w = 0, h = 0;
    if (std::sscanf(ready.c_str(), "typing bench: ready %d %d %d %d", &x, &y, &w, &h) != 4) {
        std::fprintf(stderr, "sylva-bench-typing: the studio did not get ready\n");
        kill(studio.pid, SIGTERM);
        return 1;
    }
    std::printf("%s", ready.c_str());
    const Window root = DefaultRootWindow(display);
    // The keys go where the pointer is (no window manager: focus follows the pointer).
    XWarpPointer(display, None, root, 0, 0, 0, 0, x + w / 2, y + h / 2);
    XSync(display, False);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));

    std::mt19937 random(7);
    std::uniform_int_distribution<int> gap_ms(120, 260);  // below the editor's pauses
    std::vector<double> ms;
    int missed = 0;
    std::string slow;  // "key:ms" of the keys over 50 ms
    for (int i = 0; i < keys; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(gap_ms(random)));
        const char letter[2] = {static_cast<char>('a' + i % 26), 0};
        const unsigned code = XKeysymToKeycode(display, XStringToKeysym(letter));
        const std::vector<char> before = grab(display, root, x, y, w, h);
        const Clock::time_point pressed = Clock::now();
        fake_key(display, code, True, 0);
        fake_key(display, code, False, 0);
        XFlush(display);
        bool seen = false;
        while (Clock::now() - pressed < std::chrono::seconds(3)) {
            if (grab(display, root, x, y, w, h) != before) {
                seen = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(250));
        }
        if (!seen) {
            ++missed;
            continue;
        }
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - pressed).count());
        if (ms.back() > 50.0)
            slow += " " + std::to_string(i + 1) + ":" + std::to_string(std::lround(ms.back()));
    }
    int over = 0;
    for (double v : ms) over += v > 50.0 ? 1 : 0;
    std::sort(ms.begin(), ms.end());
    const auto at = [&ms](double f) {
        return ms.empty() ? 0.0
                          : ms[std::min(ms.size() - 1, static_cast<std::size_t>(f * ms.size()))];
    };
    std::printf(
        "key to glyph on screen (X key event to the editor's pixels changing): %zu keys, "
        "median %.1f ms, 90%% %.1f ms, max %.1f ms, %d over 50 ms, %d never shown\n",
        ms.size(), at(0.5), at(0.9), ms.empty() ? 0.0 : ms.back(), over, missed);
    if (!slow.empty()) std::printf("over 50 ms (key:ms):%s\n", slow.c_str());
    const std::string report = bench_line(studio);
    std::printf("%s", report.empty() ? "the studio printed no report\n" : report.c_str());
    int status = 0;
    if (report.empty()) kill(studio.pid, SIGTERM);
    waitpid(studio.pid, &status, 0);
    std::remove(file.c_str());
    XCloseDisplay(display);
    return missed == 0 && !report.empty() ? 0 : 1;
}
