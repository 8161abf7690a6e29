// The "Variants" strip under the 3D view: thumbnails of N seeds of the edited template
// (forest/variation.h: the seeds and jitter `sylva batch` uses), generated off the UI thread
// at a small budget. Clicking one makes it the edited template (an undoable edit).
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "ui/gl.h"
#include "ui/panels.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

struct VariantThumbnail {
    TreeTemplate tree;  // the template with the variant's seed and jittered parameters
    Mesh trunk, crown, leaves;
    GLuint texture = 0;
};

struct VariantsStrip {
    bool open = false;  // the window starts expanded
    int count = 6;
    float jitter = 0.1f;
    int base_seed = 1;
    std::future<std::vector<VariantThumbnail>> job;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::vector<VariantThumbnail> thumbnails;
    bool render_pending = false;
    std::string error;
};

constexpr int kThumbnailSize = 128;

// Starts generating `strip.count` variants of `tree` (cancelling a running batch).
void start_variants(VariantsStrip& strip, const TreeTemplate& tree);
bool variants_running(const VariantsStrip& strip);
// Takes a finished batch and renders its thumbnails into textures. Needs the GL context;
// call outside ImGui's frame drawing, before the main view is drawn (it binds its own
// framebuffer and viewport).
void update_variants_strip(VariantsStrip& strip);
// The side of a thumbnail when `count` of them share `width` pixels with `spacing` between
// them: at most kThumbnailSize, at least 32.
float variant_thumbnail_size(float width, int count, float spacing);
void draw_variants_strip(VariantsStrip& strip, StudioState& state, const PanelLayout& layout);
// Cancels the job and frees the textures (the GL context still current).
void release_variants_strip(VariantsStrip& strip);

}  // namespace sylva::studio
