#include "ui/template_picker.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tree/template_library.h"
#include "ui/thumbnail_render.h"

namespace sylva::studio {
namespace {

constexpr const char* kPopup = "template picker";
constexpr int kColumns = 4;
constexpr int kDrawnPerFrame = 2;  // a thumbnail is a few milliseconds under llvmpipe

// Every built-in template with the text its thumbnail is keyed by.
const std::vector<ThumbnailSource>& builtin_sources() {
    static const std::vector<ThumbnailSource> sources = [] {
        std::vector<ThumbnailSource> out;
        for (const TreeTemplate* t : builtin_templates())
            out.push_back({t->name, std::string(builtin_template_text(t->name)), *t});
        return out;
    }();
    return sources;
}

ImTextureID texture_id(GLuint texture) {
    return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture));
}

// One template's cell: its thumbnail (or a placeholder saying why there is none yet) and
// its name under it. True when clicked.
bool cell(TemplatePicker& picker, const ThumbnailSource& source, bool current, float side) {
    ImGui::PushID(source.name.c_str());
    ImGui::BeginGroup();
    const ImVec2 top_left = ImGui::GetCursorScreenPos();
    bool clicked = false;
    const auto texture = picker.textures.find(source.name);
    const TemplateThumbnails::Entry* entry =
        picker.thumbnails ? picker.thumbnails->find(source.name) : nullptr;
    if (texture != picker.textures.end() && entry && texture->second.key == entry->key) {
        clicked = ImGui::ImageButton(texture_id(texture->second.name), ImVec2(side, side),
                                     ImVec2(0, 1), ImVec2(1, 0), 2);
    } else {
        clicked = ImGui::Button("##placeholder", ImVec2(side + 4.0f, side + 4.0f));
        const bool failed = entry && entry->status == TemplateThumbnails::Status::Failed;
        const char* text = failed ? "no picture" : "drawing...";
        const ImVec2 size = ImGui::CalcTextSize(text);
        ImGui::GetWindowDrawList()->AddText(ImVec2(top_left.x + 0.5f * (side + 4.0f - size.x),
                                                   top_left.y + 0.5f * (side + 4.0f - size.y)),
                                            ImGui::GetColorU32(ImGuiCol_TextDisabled), text);
    }
    if (current)
        ImGui::GetWindowDrawList()->AddRect(
            top_left, ImVec2(top_left.x + side + 4.0f, top_left.y + side + 4.0f),
            ImGui::GetColorU32(ImGuiCol_CheckMark), 0.0f, 0, 2.0f);
    // The name under it, centred and clipped to the cell, so every cell is as wide.
    const float width = side + 4.0f;
    const ImVec2 name_at = ImGui::GetCursorScreenPos();
    const ImVec2 name = ImGui::CalcTextSize(source.name.c_str());
    const ImVec4 clip(name_at.x, name_at.y, name_at.x + width, name_at.y + name.y);
    ImGui::GetWindowDrawList()->AddText(
        nullptr, 0.0f, ImVec2(name_at.x + std::max(0.5f * (width - name.x), 0.0f), name_at.y),
        ImGui::GetColorU32(ImGuiCol_Text), source.name.c_str(), nullptr, 0.0f, &clip);
    ImGui::Dummy(ImVec2(width, name.y));
    ImGui::EndGroup();
    if (ImGui::IsItemHovered()) {
        const std::string& why = entry ? entry->error : std::string();
        ImGui::SetTooltip("%s%s%s", source.tree.description.c_str(), why.empty() ? "" : "\n",
                          why.c_str());
    }
    ImGui::PopID();
    return clicked;
}

}  // namespace

TemplatePicker::TemplatePicker() = default;
TemplatePicker::~TemplatePicker() = default;

TemplatePicker& template_picker() {
    static TemplatePicker picker;
    return picker;
}

void update_template_picker(TemplatePicker& picker, const StudioState& state) {
    if (!picker.thumbnails) return;
    picker.thumbnails->set_paused(generation_running(state));
    for (int drawn = 0; drawn < kDrawnPerFrame; ++drawn) {
        auto meshed = picker.thumbnails->take_meshed();
        if (!meshed) break;
        if (!picker.renderers) picker.renderers = std::make_unique<ThumbnailRenderers>();
        const auto& [name, meshes] = *meshed;
        std::vector<std::uint8_t> pixels;
        const GLuint texture =
            render_tree_thumbnail(meshes.trunk, meshes.crown, meshes.leaves, meshes.colors,
                                  kTemplateThumbnailSize, *picker.renderers, &pixels);
        picker.thumbnails->store(name, std::move(pixels));
        TemplatePicker::Texture& slot = picker.textures[name];
        if (slot.name) glDeleteTextures(1, &slot.name);
        slot = {picker.thumbnails->find(name)->key, texture};
    }
    // Read from the cache folder: uploaded as they are.
    for (const ThumbnailSource& source : builtin_sources()) {
        const TemplateThumbnails::Entry* entry = picker.thumbnails->find(source.name);
        if (!entry || entry->status != TemplateThumbnails::Status::Ready) continue;
        TemplatePicker::Texture& slot = picker.textures[source.name];
        if (slot.name && slot.key == entry->key) continue;
        if (slot.name) glDeleteTextures(1, &slot.name);
        slot = {entry->key, upload_thumbnail_texture(entry->pixels, kTemplateThumbnailSize)};
    }
}

bool template_picker_busy(const TemplatePicker& picker) {
    return picker.thumbnails && picker.thumbnails->busy();
}

void template_picker_row(TemplatePicker& picker, StudioState& state) {
    const std::string& current = state.tree_template.name;
    if (ImGui::Button((current + "##picker").c_str(), ImVec2(ImGui::CalcItemWidth(), 0.0f)) ||
        picker.open_requested) {
        ImGui::OpenPopup(kPopup);
        picker.open_requested = false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("pick a built-in template (its pictures show)");
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted("template");

    const ImGuiStyle& style = ImGui::GetStyle();
    const float side = static_cast<float>(kTemplateThumbnailSize);
    const float cell_width = side + 4.0f + style.ItemSpacing.x;
    const float cell_height =
        side + 4.0f + ImGui::GetTextLineHeightWithSpacing() + style.ItemSpacing.y;
    const int rows = (static_cast<int>(builtin_sources().size()) + kColumns - 1) / kColumns;
    const float width = kColumns * cell_width + 2.0f * style.WindowPadding.x + style.ScrollbarSize;
    const float height =
        std::min(static_cast<float>(rows) * cell_height + 2.0f * style.WindowPadding.y,
                 0.8f * ImGui::GetIO().DisplaySize.y);
    const ImVec2 below(ImGui::GetItemRectMin().x, ImGui::GetItemRectMax().y);
    ImGui::SetNextWindowPos(ImVec2(std::max(below.x - cell_width, 0.0f), below.y),
                            ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(width, height));
    picker.open = ImGui::BeginPopup(kPopup);
    if (!picker.open) return;
    if (!picker.thumbnails)
        picker.thumbnails =
            std::make_unique<TemplateThumbnails>(picker.folder, make_thumbnail_meshes, picker.wake);
    if (ImGui::IsWindowAppearing()) picker.thumbnails->request(builtin_sources());
    int column = 0;
    for (const ThumbnailSource& source : builtin_sources()) {
        if (column > 0) ImGui::SameLine();
        if (cell(picker, source, source.name == current, side)) {
            switch_template(state, {source.tree, {}, {}});
            ImGui::CloseCurrentPopup();
        }
        column = (column + 1) % kColumns;
    }
    ImGui::EndPopup();
}

void release_template_picker(TemplatePicker& picker) {
    picker.thumbnails.reset();  // joins the worker
    for (auto& [name, texture] : picker.textures)
        if (texture.name) glDeleteTextures(1, &texture.name);
    picker.textures.clear();
    picker.renderers.reset();
}

}  // namespace sylva::studio
