// Keyboard input handed to ImGui a frame's worth at a time. ImGui 1.86 reads key state once
// per frame, so a key pressed and released between two frames never reaches it, and
// characters typed after a key arrive before it: under a software renderer drawing a few
// frames a second, typing "ab", Backspace, "c" quickly lost the Backspace. The queue takes
// GLFW's key and character events in order and delivers, each frame, events up to the point
// where the order would be lost: the release of a key pressed in the same frame, or a
// character after an editing key's press (Backspace, arrows, Ctrl+...: ImGui handles a
// frame's characters before its keys). What is
// left waits for the next frame (ImGui 1.87 added such a queue of its own).
//
// Thread safety: the UI thread only (GLFW calls its callbacks from glfwPollEvents there).
#pragma once

#include <cstddef>
#include <span>

struct GLFWwindow;

namespace sylva::studio {

struct InputEvent {
    enum Kind { Key, Char } kind = Key;
    int key = 0, scancode = 0, action = 0, mods = 0;  // Key: GLFW's values
    unsigned codepoint = 0;                           // Char
};

// How many of `events` (oldest first) one frame takes: at least one when there are any.
std::size_t events_for_one_frame(std::span<const InputEvent> events);

// Puts the queue between GLFW and ImGui's GLFW backend: call after
// ImGui_ImplGlfw_InitForOpenGL(window, true), which installed the callbacks it wraps.
void install_input_queue(GLFWwindow* window);

// Delivers one frame's events to ImGui (and through its chain to the studio's own key
// callback). Call before ImGui_ImplGlfw_NewFrame().
void deliver_input_events(GLFWwindow* window);

// True while events wait for a later frame: the loop should draw again without waiting.
bool input_events_waiting();

}  // namespace sylva::studio
