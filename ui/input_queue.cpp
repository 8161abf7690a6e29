#include "ui/input_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <vector>

namespace sylva::studio {
namespace {

std::vector<InputEvent> g_events;
GLFWkeyfun g_imgui_key = nullptr;
GLFWcharfun g_imgui_char = nullptr;

void queue_key(GLFWwindow* /*window*/, int key, int scancode, int action, int mods) {
    g_events.push_back({InputEvent::Key, key, scancode, action, mods, 0});
}

void queue_char(GLFWwindow* /*window*/, unsigned codepoint) {
    g_events.push_back({InputEvent::Char, 0, 0, 0, 0, codepoint});
}

// A key a text field acts on (Backspace, the arrows, Enter, Ctrl+A, ...) rather than one
// that only types its character; modifier keys are neither.
bool editing_key(const InputEvent& e) {
    if (e.key >= GLFW_KEY_LEFT_SHIFT && e.key <= GLFW_KEY_RIGHT_SUPER) return false;
    return e.key >= GLFW_KEY_ESCAPE || (e.mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0;
}

}  // namespace

std::size_t events_for_one_frame(std::span<const InputEvent> events) {
    std::vector<int> pressed;   // keys that went down in this frame
    std::vector<int> released;  // ... and up
    bool edited = false;        // ... one of them an editing key
    std::size_t n = 0;
    for (const InputEvent& e : events) {
        if (e.kind == InputEvent::Char) {
            if (edited) break;  // it would be typed before the key acts
        } else if (e.action == GLFW_RELEASE) {
            if (std::find(pressed.begin(), pressed.end(), e.key) != pressed.end()) break;
            released.push_back(e.key);
        } else if (e.action == GLFW_PRESS) {
            // ImGui sees a press only when the key was up the frame before: a key that went
            // up or down in this frame waits. (Repeats change no key state; ImGui repeats a
            // held key itself.)
            if (std::find(pressed.begin(), pressed.end(), e.key) != pressed.end() ||
                std::find(released.begin(), released.end(), e.key) != released.end())
                break;
            pressed.push_back(e.key);
            edited |= editing_key(e);
        }
        ++n;
    }
    return std::max<std::size_t>(n, events.empty() ? 0 : 1);
}

void install_input_queue(GLFWwindow* window) {
    g_imgui_key = glfwSetKeyCallback(window, queue_key);
    g_imgui_char = glfwSetCharCallback(window, queue_char);
}

void deliver_input_events(GLFWwindow* window) {
    const std::size_t n = events_for_one_frame(g_events);
    for (std::size_t i = 0; i < n; ++i) {
        const InputEvent& e = g_events[i];
        if (e.kind == InputEvent::Key && g_imgui_key)
            g_imgui_key(window, e.key, e.scancode, e.action, e.mods);
        else if (e.kind == InputEvent::Char && g_imgui_char)
            g_imgui_char(window, e.codepoint);
    }
    g_events.erase(g_events.begin(), g_events.begin() + static_cast<std::ptrdiff_t>(n));
}

bool input_events_waiting() {
    return !g_events.empty();
}

}  // namespace sylva::studio
