#include "turtle/turtle.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/pipe_model.h"

namespace sylva {
namespace {

// The largest colour index '(i) keeps; beyond it (or for NaN and negative values) the
// index is clamped rather than converted out of range.
constexpr double kMaxColourIndex = 1'000'000.0;

int colour_index(double value) {
    if (!(value > 0.0)) return 0;
    return static_cast<int>(std::min(std::floor(value), kMaxColourIndex));
}

constexpr double kDegree = std::numbers::pi / 180.0;

struct State {
    glm::dvec3 position{0.0};
    glm::dvec3 heading{0.0, 1.0, 0.0};
    glm::dvec3 left{-1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 0.0, 1.0};
    double elevation = 0.0;  // LPTG, degrees
    double azimuth = 0.0;    // LPTG, degrees
    double width = 0.0;
    int color = 0;
    int parent = -1;
    int depth = 0;
};

// Rotates the pair (a, b) in their plane: a' = a cos t + b sin t, b' = b cos t - a sin t.
void rotate_pair(glm::dvec3& a, glm::dvec3& b, double degrees) {
    double c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
    glm::dvec3 a2 = a * c + b * s;
    b = b * c - a * s;
    a = a2;
}

// Rodrigues rotation of v about the unit axis k.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& k, double radians) {
    double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

// Keeps the frame orthonormal against drift over long words.
void orthonormalize(State& s) {
    s.heading = glm::normalize(s.heading);
    s.left = glm::normalize(s.left - s.heading * glm::dot(s.left, s.heading));
    s.up = glm::cross(s.heading, s.left);
}

class Interpreter {
  public:
    Interpreter(const Word& word, const TurtleSettings& settings)
        : word_(word), settings_(settings) {
        state_.width = settings.initial_width;
    }

    Skeleton run() {
        for (size_t i = 0; i < word_.size(); ++i) {
            if (i % 4096 == 0) throw_if_cancelled(settings_.cancel);
            std::span<const double> a = word_.args(i);
            auto arg = [&](double fallback) { return a.empty() ? fallback : a[0]; };
            switch (word_.symbol(i)) {
                case 'F':
                    forward(arg(settings_.step), true);
                    break;
                case 'f':
                    forward(arg(settings_.step), false);
                    break;
                case '+':
                    turn(arg(settings_.turn_angle));
                    break;
                case '-':
                    turn(-arg(settings_.turn_angle));
                    break;
                case '&':
                    pitch(arg(settings_.pitch_angle));
                    break;
                case '^':
                    pitch(-arg(settings_.pitch_angle));
                    break;
                case '\\':
                    roll(arg(settings_.roll_angle));
                    break;
                case '/':
                    roll(-arg(settings_.roll_angle));
                    break;
                case '|':
                    turn_around();
                    break;
                case '$':
                    roll_to_vertical();
                    break;
                case '[':
                    stack_.push_back(state_);
                    ++state_.depth;
                    break;
                case ']':
                    if (stack_.empty())
                        throw GrammarError("the derived word has a ']' with no '[' (module " +
                                           std::to_string(i + 1) + ")");
                    state_ = stack_.back();
                    stack_.pop_back();
                    break;
                case '!':
                    state_.width = a.empty() ? state_.width * settings_.width_decay : a[0];
                    break;
                case '\'':
                    state_.color = colour_index(a.empty() ? state_.color + 1.0 : a[0]);
                    break;
                case '{':
                    polygons_.emplace_back();
                    break;
                case '.':
                    if (!polygons_.empty()) polygons_.back().push_back(glm::vec3(state_.position));
                    break;
                case '}':
                    close_polygon(i);
                    break;
                case '%':
                    i = end_of_branch(i);
                    break;
                default:
                    break;  // other symbols only drive the derivation
            }
        }
        if (settings_.width_model == WidthModel::Pipe)
            apply_pipe_model(out_, static_cast<float>(settings_.pipe_tip_width * 0.5),
                             static_cast<float>(settings_.pipe_exponent));
        return std::move(out_);
    }

  private:
    void forward(double length, bool draw) {
        glm::dvec3 direction =
            settings_.mode == TurtleMode::Lptg ? lptg_direction() : state_.heading;
        glm::dvec3 start = state_.position;
        state_.position += direction * length;
        if (draw && length != 0.0) {
            Segment s;
            s.a = glm::vec3(start);
            s.b = glm::vec3(state_.position);
            s.ra = static_cast<float>(state_.width * 0.5);
            if (settings_.width_model == WidthModel::Taper)
                state_.width *= state_.depth == 0 ? settings_.trunk_taper : settings_.branch_taper;
            s.rb = static_cast<float>(state_.width * 0.5);
            s.parent = state_.parent;
            s.depth = state_.depth;
            s.color = state_.color;
            state_.parent = static_cast<int>(out_.segments.size());
            out_.segments.push_back(s);
        }
        if (settings_.mode == TurtleMode::Abop) apply_tropism();
    }

    glm::dvec3 lptg_direction() const {
        double e = state_.elevation * kDegree, a = state_.azimuth * kDegree;
        return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
    }

    void apply_tropism() {
        if (settings_.elasticity == 0.0) return;
        glm::dvec3 axis = glm::cross(state_.heading, settings_.tropism);
        double strength = glm::length(axis);
        if (strength < 1e-12) return;
        axis /= strength;
        double angle = settings_.elasticity * strength;
        state_.heading = rotate(state_.heading, axis, angle);
        state_.left = rotate(state_.left, axis, angle);
        orthonormalize(state_);
    }

    void turn(double degrees) {
        if (settings_.mode == TurtleMode::Lptg) {
            state_.azimuth += degrees;
            return;
        }
        rotate_pair(state_.heading, state_.left, degrees);
        orthonormalize(state_);
    }
    void pitch(double degrees) {
        if (settings_.mode == TurtleMode::Lptg) {
            state_.elevation -= degrees;  // '&' pitches down, '^' up
            return;
        }
        rotate_pair(state_.heading, state_.up, -degrees);  // H' = H cos a - U sin a
        orthonormalize(state_);
    }
    void roll(double degrees) {
        if (settings_.mode == TurtleMode::Lptg) return;
        rotate_pair(state_.left, state_.up, degrees);
        orthonormalize(state_);
    }
    void turn_around() {
        if (settings_.mode == TurtleMode::Lptg) {
            state_.azimuth += 180.0;
            state_.elevation = -state_.elevation;
            return;
        }
        state_.heading = -state_.heading;
        state_.left = -state_.left;
    }
    void roll_to_vertical() {
        if (settings_.mode == TurtleMode::Lptg) return;
        glm::dvec3 l = glm::cross(glm::dvec3(0.0, 1.0, 0.0), state_.heading);
        double n = glm::length(l);
        if (n < 1e-12) return;  // heading is vertical: every roll is "vertical"
        state_.left = l / n;
        state_.up = glm::cross(state_.heading, state_.left);
    }

    void close_polygon(size_t i) {
        if (polygons_.empty())
            throw GrammarError("the derived word has a '}' with no '{' (module " +
                               std::to_string(i + 1) + ")");
        if (polygons_.back().size() >= 3) out_.polygons.push_back(std::move(polygons_.back()));
        polygons_.pop_back();
    }

    // '%' cuts the rest of the branch: continue at its closing ']' (or the word's end).
    size_t end_of_branch(size_t i) const {
        int depth = 0;
        for (size_t k = i + 1; k < word_.size(); ++k) {
            char c = word_.symbol(k);
            if (c == '[') ++depth;
            if (c == ']' && depth-- == 0) return k - 1;
        }
        return word_.size();
    }

    const Word& word_;
    const TurtleSettings& settings_;
    State state_;
    std::vector<State> stack_;
    std::vector<std::vector<glm::vec3>> polygons_;
    Skeleton out_;
};

}  // namespace

Skeleton interpret(const Word& word, const TurtleSettings& settings) {
    return Interpreter(word, settings).run();
}

}  // namespace sylva
