// Saves what the GL context has drawn as a PNG, for scripted screenshots and the UI test.
#pragma once

#include <string>

namespace sylva::studio {

// Reads the current back buffer (call before swapping), `width` x `height` pixels from the
// lower-left corner, flips it to top-row-first and writes an RGB PNG at `path`.
// Throws sylva::IoError naming the path when the file cannot be written.
void save_back_buffer_png(const std::string& path, int width, int height);
// The same for the rectangle whose lower-left corner is (x, y): the 3D view alone.
void save_back_buffer_png(const std::string& path, int x, int y, int width, int height);

}  // namespace sylva::studio
