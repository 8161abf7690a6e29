#include "ui/forest_preview.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace sylva::studio {
namespace {

bool same_options(const ForestPreviewOptions& a, const ForestPreviewOptions& b) {
    return a.size == b.size && a.variants == b.variants;
}

bool finished(const std::future<ForestPreviewMeshes>& job) {
    return job.valid() && job.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void drop_finished_stale(ForestPreview& p) {
    std::erase_if(p.stale, [](const std::future<ForestPreviewMeshes>& j) { return finished(j); });
}

void cancel_job(ForestPreview& p) {
    if (!p.job.valid()) return;
    p.cancel->store(true);
    p.stale.push_back(std::move(p.job));
    p.has_job = false;
}

void start_job(ForestPreview& p, const TreeTemplate& tree, const ForestPreviewOptions& options,
               const ForestPreviewPlan& plan) {
    cancel_job(p);
    p.cancel = std::make_shared<std::atomic<bool>>(false);
    p.done = std::make_shared<std::atomic<int>>(0);
    p.total = std::make_shared<std::atomic<int>>(options.variants);
    p.job_template = tree;
    p.job_options = options;
    p.job_plan = plan;
    p.has_job = true;
    p.error.clear();
    p.job = std::async(std::launch::async,
                       [tree, options, plan, cancel = p.cancel, done = p.done, total = p.total] {
                           return make_forest_preview(
                               tree, options, cancel.get(),
                               [&](int d, int t) {
                                   total->store(t);
                                   done->store(d);
                               },
                               plan);
                       });
}

void upload(ForestPreview& p, const ForestPreviewMeshes& m) {
    if (!p.trunk) {
        p.trunk = std::make_unique<MeshRenderer>();
        p.crown = std::make_unique<MeshRenderer>();
        p.leaves = std::make_unique<MeshRenderer>();
    }
    p.trunk->upload(m.trunk);
    p.crown->upload(m.crown);
    p.leaves->upload(m.leaves);
    p.trees = m.trees;
    p.triangles = m.trunk.triangles.size() + m.crown.triangles.size() + m.leaves.triangles.size();
    p.low = m.low;
    p.high = m.high;
    p.ready = true;
    p.shown_template = p.job_template;
    p.shown_options = p.job_options;
    p.shown_plan = p.job_plan;
}

}  // namespace

void forest_preview_row(StudioState& state) {
    ViewToggles& v = state.view;
    ImGui::Checkbox("forest", &v.forest);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "plant a square of forest with this template as its only species (sylva forest's "
            "spacing, %d-triangle variants); the tree stays until the forest is ready",
            static_cast<int>(kForestPreviewBudget));
    ImGui::SameLine();
    ImGui::BeginDisabled(!v.forest);
    ImGui::SetNextItemWidth(110.0f);
    ImGui::SliderFloat("##forest_size", &v.forest_options.size, kForestPreviewMinSize,
                       kForestPreviewMaxSize, "%.0f m");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("each side of the planted square");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    ImGui::SliderInt("##forest_k", &v.forest_options.variants, 1, kForestPreviewMaxVariants,
                     "K %d");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("unique variants of the template the trees are drawn from");
    ImGui::EndDisabled();
    if (v.forest && !state.forest_status.empty())
        ImGui::TextUnformatted(state.forest_status.c_str());
}

bool update_forest_preview(ForestPreview& p, StudioState& state) {
    drop_finished_stale(p);
    bool frame = false;
    if (finished(p.job)) {
        try {
            // A first forest or another size of square: the camera follows the area.
            const bool new_area = !p.ready || p.shown_options.size != p.job_options.size ||
                                  p.shown_plan.id != p.job_plan.id;
            upload(p, p.job.get());
            frame = p.frame_pending || new_area;
            p.frame_pending = false;
        } catch (const Cancelled&) {
        } catch (const std::exception& e) {
            p.error = e.what();
        }
    }
    const bool on = state.view.forest;
    if (on != p.was_on) {
        p.was_on = on;
        if (on)
            p.frame_pending = true;
        else
            state.frame_requested = true;  // back to the single tree
    }
    if (!on) {
        cancel_job(p);
        state.forest_status.clear();
        return false;
    }
    // Sliders held: wait for the release rather than plant every step of the drag.
    if (state.tree && !state.dragging) {
        const ForestPreviewOptions& wanted = state.view.forest_options;
        const std::uint64_t plan = state.view.forest_plan.id;
        const bool shown_current = p.ready &&
                                   same_template(p.shown_template, state.shown_template) &&
                                   same_options(p.shown_options, wanted) && p.shown_plan.id == plan;
        const bool job_current = p.has_job && same_template(p.job_template, state.shown_template) &&
                                 same_options(p.job_options, wanted) && p.job_plan.id == plan;
        if (!job_current && !shown_current)
            start_job(p, state.shown_template, wanted, state.view.forest_plan);
    }
    if (p.job.valid()) {
        char text[96];
        std::snprintf(text, sizeof text, "planting: %d of %d variants made", p.done->load(),
                      p.total->load());
        state.forest_status = text;
    } else if (!p.error.empty()) {
        state.forest_status = "forest: " + p.error;
    } else if (p.ready) {
        char text[96];
        std::snprintf(text, sizeof text, "%zu trees, %zu triangles", p.trees, p.triangles);
        state.forest_status = text;
    }
    if (p.ready && p.frame_pending && !p.job.valid()) {
        frame = true;
        p.frame_pending = false;
    }
    return frame;
}

bool forest_preview_shown(const ForestPreview& p, const StudioState& state) {
    return state.view.forest && p.ready;
}

bool forest_preview_running(const ForestPreview& p) {
    return p.job.valid();
}

std::vector<glm::vec3> forest_preview_frame_points(const ForestPreview& p) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < 8; ++i)
        points.emplace_back(i & 1 ? p.high.x : p.low.x, i & 2 ? p.high.y : std::min(p.low.y, 0.0f),
                            i & 4 ? p.high.z : p.low.z);
    return points;
}

void release_forest_preview(ForestPreview& p) {
    if (p.cancel) p.cancel->store(true);
    if (p.job.valid()) p.job.wait();
    for (std::future<ForestPreviewMeshes>& job : p.stale) job.wait();
    p.stale.clear();
}

}  // namespace sylva::studio
