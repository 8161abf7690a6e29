// The template picker: a button naming the edited template that opens a grid of every
// built-in template as a thumbnail of its default tree. The thumbnails are made once, on a
// worker, at the picker's first opening and cached in the user's cache folder under a hash
// of the template's text (ui/state/template_thumbnails.h); a placeholder shows until each is
// drawn, one or two a frame, so the window never waits for them.
//
// UI thread only; update_template_picker() needs the GL context.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "ui/gl.h"
#include "ui/state/studio_state.h"
#include "ui/state/template_thumbnails.h"

namespace sylva::studio {

struct ThumbnailRenderers;

struct TemplatePicker {
    // Where the thumbnails persist (thumbnail_cache_folder(); empty: memory only) and what
    // wakes the window when a thumbnail's meshes are made. Read at the first opening.
    std::filesystem::path folder;
    std::function<void()> wake;
    std::unique_ptr<TemplateThumbnails> thumbnails;  // made at the first opening
    struct Texture {
        std::uint64_t key = 0;  // the thumbnail's key it shows
        GLuint name = 0;
    };
    std::map<std::string, Texture, std::less<>> textures;
    std::unique_ptr<ThumbnailRenderers> renderers;
    bool open_requested = false;  // open the grid on the next frame (--template-picker)
    bool open = false;            // the grid was open in the last frame
    TemplatePicker();
    ~TemplatePicker();
};

// The studio's one picker (the Tree panel draws it, main updates and releases it).
TemplatePicker& template_picker();

// Draws the thumbnails whose meshes are made (at most two a frame) and uploads those read
// from the cache; pauses the worker while a generation runs. Needs the GL context; call
// before the frame's panels, outside ImGui's drawing.
void update_template_picker(TemplatePicker& picker, const StudioState& state);

// True while the picker was opened and a thumbnail is still to be made or drawn.
bool template_picker_busy(const TemplatePicker& picker);

// The "template" row of the Tree panel and its grid; picking one switches to it (asking
// first over unsaved edits: switch_template()).
void template_picker_row(TemplatePicker& picker, StudioState& state);

// Stops the worker and frees the textures (the GL context still current).
void release_template_picker(TemplatePicker& picker);

}  // namespace sylva::studio
