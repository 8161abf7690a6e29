#include "ui/variants_strip.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/cancel.h"
#include "core/color_variation.h"
#include "forest/variation.h"
#include "ui/thumbnail_render.h"

namespace sylva::studio {
namespace {

constexpr std::size_t kThumbnailBudget = 300;

std::vector<VariantThumbnail> make_variants(TreeTemplate tree, int count, double jitter,
                                            std::uint64_t base, std::atomic<bool>* cancel) {
    std::vector<VariantThumbnail> out;
    FinishSettings finish;
    finish.budget.total = kThumbnailBudget;
    finish.decimate.cancel = cancel;
    MeshOptions mesh;
    mesh.budget = kThumbnailBudget;
    mesh.cancel = cancel;
    for (int i = 0; i < count; ++i) {
        VariantThumbnail t;
        t.tree = tree;
        t.tree.params =
            varied_params(tree.params, variant_seed(base, static_cast<std::uint64_t>(i)), jitter);
        const Tree generated = generate_tree(t.tree, mesh);
        const FinishedTree finished = finish_tree(generated, finish);
        t.trunk = finished.levels[0].trunk;
        t.crown = finished.levels[0].crown;
        t.leaves = finished.levels[0].leaves;
        out.push_back(std::move(t));
    }
    return out;
}

void free_textures(std::vector<VariantThumbnail>& thumbnails) {
    for (VariantThumbnail& t : thumbnails)
        if (t.texture) glDeleteTextures(1, &t.texture);
    thumbnails.clear();
}

}  // namespace

void start_variants(VariantsStrip& strip, const TreeTemplate& tree) {
    if (strip.cancel) strip.cancel->store(true);
    if (strip.job.valid()) strip.job.wait();  // a cancelled batch stops at its next check
    strip.cancel = std::make_shared<std::atomic<bool>>(false);
    strip.error.clear();
    strip.job = std::async(std::launch::async, make_variants, tree, strip.count,
                           static_cast<double>(strip.jitter),
                           static_cast<std::uint64_t>(strip.base_seed), strip.cancel.get());
}

bool variants_running(const VariantsStrip& strip) {
    return strip.job.valid() || strip.render_pending;
}

void update_variants_strip(VariantsStrip& strip) {
    if (strip.job.valid() &&
        strip.job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        try {
            std::vector<VariantThumbnail> made = strip.job.get();
            free_textures(strip.thumbnails);
            strip.thumbnails = std::move(made);
            strip.render_pending = true;
        } catch (const Cancelled&) {
        } catch (const std::exception& e) {
            strip.error = e.what();
        }
    }
    if (!strip.render_pending) return;
    ThumbnailRenderers renderers;
    for (VariantThumbnail& t : strip.thumbnails)
        if (!t.texture)
            t.texture = render_tree_thumbnail(t.trunk, t.crown, t.leaves, tree_colors(t.tree),
                                              kThumbnailSize, renderers);
    strip.render_pending = false;
}

float variant_thumbnail_size(float width, int count, float spacing) {
    const int n = std::max(count, 1);
    const float fit = (width - spacing * static_cast<float>(n - 1)) / static_cast<float>(n);
    return std::clamp(std::floor(fit), 32.0f, static_cast<float>(kThumbnailSize));
}

void draw_variants_strip(VariantsStrip& strip, StudioState& state, const PanelLayout& layout) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = layout.width - layout.left - layout.right;
    // The thumbnails shrink to fit the window's width side by side; the controls wrap.
    const int shown_count =
        strip.thumbnails.empty() ? strip.count : static_cast<int>(strip.thumbnails.size());
    const float thumb = variant_thumbnail_size(width - 2.0f * style.WindowPadding.x, shown_count,
                                               style.ItemSpacing.x);
    const float controls_width = 3.0f * 150.0f + 120.0f;
    const int control_rows = width - 2.0f * style.WindowPadding.x >= controls_width ? 1 : 2;
    const float height = ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y +
                         static_cast<float>(control_rows) * ImGui::GetFrameHeightWithSpacing() +
                         thumb + ImGui::GetTextLineHeightWithSpacing() + style.ItemSpacing.y;
    // Collapsed, only the title bar shows: it sits on the status bar, not over the tree.
    const float shown = strip.open ? height : ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(layout.left, layout.height - layout.bottom - shown),
                            ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    ImGui::SetNextWindowCollapsed(!strip.open, ImGuiCond_Always);  // the View menu opens it
    strip.open =
        ImGui::Begin("Variants", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    if (!strip.open) {
        ImGui::End();
        return;
    }
    ImGui::SetNextItemWidth(100);
    ImGui::SliderInt("count", &strip.count, 1, 12);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100);
    ImGui::SliderFloat("jitter", &strip.jitter, 0.0f, 1.0f, "%.2f");
    if (control_rows == 1) ImGui::SameLine();
    ImGui::SetNextItemWidth(100);
    ImGui::InputInt("seed", &strip.base_seed);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the first variant's seed; the others follow from it (sylva batch's)");
    ImGui::SameLine();
    if (ImGui::Button(strip.job.valid() ? "making..." : "Make variants"))
        start_variants(strip, state.tree_template);
    if (!strip.error.empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", strip.error.c_str());
    for (std::size_t i = 0; i < strip.thumbnails.size(); ++i) {
        const VariantThumbnail& t = strip.thumbnails[i];
        if (!t.texture) continue;
        if (i > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(t.texture)),
                     ImVec2(thumb, thumb), ImVec2(0, 1), ImVec2(1, 0));
        const bool clicked = ImGui::IsItemClicked();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("variant %zu (seed %llu): click to edit this variant", i + 1,
                              static_cast<unsigned long long>(t.tree.params.seed));
        ImGui::Text("%zu", i + 1);
        ImGui::EndGroup();
        if (clicked) load_template_into(state, t.tree);
    }
    ImGui::End();
}

void release_variants_strip(VariantsStrip& strip) {
    if (strip.cancel) strip.cancel->store(true);
    if (strip.job.valid()) strip.job.wait();
    free_textures(strip.thumbnails);
}

}  // namespace sylva::studio
