#include "turtle/turtle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/noise.h"
#include "core/pipe_model.h"
#include "core/random.h"

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
    // Variation: which branch the turtle is on (0: the trunk; each '[' starts a new one),
    // how far along it, and the branch's jitter factors.
    int branch = 0;
    double arc = 0.0;
    double length_factor = 1.0;
    double angle_factor = 1.0;
};

// A branch's coordinate across the noise: far enough apart that branches bend independently.
double branch_coordinate(int branch) {
    return 0.5 + 1.7320508075688772 * branch;
}

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

// A polygon being drawn: the outline its moves trace (from where '{' stood), the vertices
// its '.' marks, and its colour index.
struct OpenPolygon {
    std::vector<glm::vec3> traced;
    std::vector<glm::vec3> dotted;
    int color = 0;
};

// Drops vertices that repeat the one before, and a last one that returns to the first (ABOP's
// leaves trace back to where they started): the outline without zero-length edges.
std::vector<glm::vec3> clean_outline(const std::vector<glm::vec3>& traced) {
    constexpr float kSame = 1e-6f;
    std::vector<glm::vec3> out;
    for (const glm::vec3& v : traced)
        if (out.empty() || glm::distance(v, out.back()) > kSame) out.push_back(v);
    while (out.size() > 1 && glm::distance(out.back(), out.front()) <= kSame) out.pop_back();
    return out;
}

class Interpreter {
  public:
    Interpreter(const Word& word, const TurtleSettings& settings,
                std::vector<glm::vec3>* positions = nullptr)
        : word_(word),
          settings_(settings),
          bend_pitch_(derive_seed(settings.seed, noise_stream::bend), settings.noise_kind),
          bend_turn_(derive_seed(derive_seed(settings.seed, noise_stream::bend), 1),
                     settings.noise_kind),
          width_(derive_seed(settings.seed, noise_stream::width), settings.noise_kind),
          tropism_{
              NoiseField(derive_seed(settings.seed, noise_stream::tropism), settings.noise_kind),
              NoiseField(derive_seed(derive_seed(settings.seed, noise_stream::tropism), 1),
                         settings.noise_kind),
              NoiseField(derive_seed(derive_seed(settings.seed, noise_stream::tropism), 2),
                         settings.noise_kind)},
          jitter_seed_(derive_seed(settings.seed, noise_stream::jitter)),
          positions_(positions) {
        state_.width = settings.initial_width;
        start_branch();
        // Word modules named "~name" place the organ `name`; other words only drive the
        // derivation.
        if (const auto& names = word.names())
            for (std::size_t k = 0; k < names->size(); ++k)
                if ((*names)[k].size() > 1 && (*names)[k][0] == '~')
                    surfaces_[k] = (*names)[k].substr(1);
    }

    Skeleton run() {
        if (positions_) positions_->assign(word_.size(), glm::vec3(0.0f));
        for (size_t i = 0; i < word_.size(); ++i) {
            if (i % 4096 == 0) {
                throw_if_cancelled(settings_.cancel);
                if (settings_.progress)
                    settings_.progress(static_cast<float>(i) / static_cast<float>(word_.size()));
            }
            if (positions_) (*positions_)[i] = glm::vec3(state_.position);
            std::span<const double> a = word_.args(i);
            auto arg = [&](double fallback) { return a.empty() ? fallback : a[0]; };
            const char symbol = word_.symbol(i);
            if (is_word_symbol(symbol)) {
                place_organ(symbol, a);
                continue;
            }
            switch (symbol) {
                case 'F':
                    forward(arg(settings_.step), true);
                    break;
                case 'f':
                    forward(arg(settings_.step), false);
                    break;
                case 'G':
                    forward(arg(settings_.step), true, false);
                    break;
                case 'g':
                    forward(arg(settings_.step), false, false);
                    break;
                case '+':
                    turn(state_.angle_factor * arg(settings_.turn_angle));
                    break;
                case '-':
                    turn(-state_.angle_factor * arg(settings_.turn_angle));
                    break;
                case '&':
                    pitch(state_.angle_factor * arg(settings_.pitch_angle));
                    break;
                case '^':
                    pitch(-state_.angle_factor * arg(settings_.pitch_angle));
                    break;
                case '\\':
                    roll(state_.angle_factor * arg(settings_.roll_angle));
                    break;
                case '/':
                    roll(-state_.angle_factor * arg(settings_.roll_angle));
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
                    state_.branch = ++branches_;
                    start_branch();
                    break;
                case ']':
                    if (stack_.empty()) {
                        if (positions_) break;
                        throw GrammarError("the derived word has a ']' with no '[' (module " +
                                           std::to_string(i + 1) + ")");
                    }
                    state_ = stack_.back();
                    stack_.pop_back();
                    break;
                case '!':
                    state_.width = a.empty() ? state_.width * settings_.width_decay : a[0];
                    break;
                case '\'':
                    state_.color = colour_index(a.empty() ? state_.color + 1.0 : a[0]);
                    break;
                case ';':
                    state_.color = colour_index(a.empty() ? state_.color - 1.0 : a[0]);
                    break;
                case '{':
                    polygons_.push_back({{glm::vec3(state_.position)}, {}, state_.color});
                    break;
                case '.':
                    if (!polygons_.empty())
                        polygons_.back().dotted.push_back(glm::vec3(state_.position));
                    break;
                case '}':
                    close_polygon(i);
                    break;
                case '%': {
                    const size_t end = end_of_branch(i);
                    if (positions_)
                        for (size_t k = i + 1; k <= end && k < word_.size(); ++k)
                            (*positions_)[k] = glm::vec3(state_.position);
                    i = end;
                    break;
                }
                default:
                    break;  // other symbols only drive the derivation
            }
        }
        if (settings_.width_model == WidthModel::Pipe)
            apply_pipe_model(out_, static_cast<float>(settings_.pipe_tip_width * 0.5),
                             static_cast<float>(settings_.pipe_exponent));
        vary_widths();
        if (settings_.progress) settings_.progress(1.0f);
        return std::move(out_);
    }

  private:
    // A new branch (or the trunk): its jitter factors, from its own draw of the seed.
    void start_branch() {
        state_.arc = 0.0;
        if (settings_.jitter == 0.0) return;
        Random random(derive_seed(jitter_seed_, static_cast<std::uint64_t>(state_.branch)));
        state_.length_factor = 1.0 + settings_.jitter * (2.0 * random.uniform() - 1.0);
        state_.angle_factor = 1.0 + settings_.jitter * (2.0 * random.uniform() - 1.0);
    }

    // Width variation after every width model: radii times 1 + v * noise along the branch,
    // continuous where one segment meets the next on the same branch.
    void vary_widths() {
        const double v = settings_.width_variation;
        if (v == 0.0) return;
        auto factor = [&](size_t i, double s) {
            const double n =
                width_(s * settings_.bend_frequency, branch_coordinate(span_branch_[i]));
            return static_cast<float>(std::max(0.05, 1.0 + v * n));
        };
        for (size_t i = 0; i < out_.segments.size(); ++i) {
            out_.segments[i].ra *= factor(i, span_start_[i]);
            out_.segments[i].rb *= factor(i, span_end_[i]);
        }
    }

    // The organ a "~name" word places, in the turtle's frame; its parameter is its size.
    void place_organ(char symbol, std::span<const double> a) {
        const std::string& surface = surfaces_[static_cast<std::size_t>(
            static_cast<unsigned char>(symbol) - kFirstWordSymbol)];
        if (surface.empty()) return;
        Organ organ;
        organ.surface = surface;
        organ.position = glm::vec3(state_.position);
        organ.heading =
            glm::vec3(settings_.mode == TurtleMode::Lptg ? lptg_direction() : state_.heading);
        organ.left = glm::vec3(state_.left);
        organ.up = glm::vec3(state_.up);
        const double size = a.empty() ? 0.0 : a[0];
        organ.size =
            std::isfinite(size) && size > 0.0 ? static_cast<float>(std::min(size, 1e6)) : 0.0f;
        organ.color = state_.color;
        out_.organs.push_back(std::move(organ));
    }

    // Inside a polygon, a move that records (F, f) adds the point it reaches to the outline.
    void forward(double length, bool draw, bool record = true) {
        forward_move(length, draw);
        if (record && !polygons_.empty())
            polygons_.back().traced.push_back(glm::vec3(state_.position));
    }

    // The turtle's step with bending: pieces an eighth of a noise cycle long, each turned by
    // the curvature noise at its middle (bend degrees per meter at noise 1).
    void forward_move(double length, bool draw) {
        length *= state_.length_factor;
        if (settings_.bend == 0.0) return forward_piece(length, draw, 1.0, true);
        const double piece = 0.125 / settings_.bend_frequency;
        const int pieces = std::clamp(static_cast<int>(std::ceil(std::abs(length) / piece)), 1, 32);
        const double width0 = state_.width;
        const double taper = !draw || settings_.width_model != WidthModel::Taper ? 1.0
                             : state_.depth == 0 ? settings_.trunk_taper
                                                 : settings_.branch_taper;
        const double step = length / pieces;
        for (int k = 0; k < pieces; ++k) {
            // Widths run linearly from the F's start to its tapered end across the pieces.
            state_.width = width0 * (1.0 + (taper - 1.0) * k / pieces);
            const double next = width0 * (1.0 + (taper - 1.0) * (k + 1) / pieces);
            forward_piece(step, draw, state_.width > 0.0 ? next / state_.width : taper,
                          k + 1 == pieces);
            state_.width = next;
            const double y = branch_coordinate(state_.branch);
            const double s = (state_.arc - 0.5 * std::abs(step)) * settings_.bend_frequency;
            const double degrees = settings_.bend * std::abs(step);
            pitch(degrees * bend_pitch_(s, y));
            turn(degrees * bend_turn_(s, y));
        }
    }

    // One drawn (or moved) piece; `taper` is this piece's width factor, `last` whether the F
    // ends here (tropism bends once per F).
    void forward_piece(double length, bool draw, double taper, bool last) {
        glm::dvec3 direction =
            settings_.mode == TurtleMode::Lptg ? lptg_direction() : state_.heading;
        glm::dvec3 start = state_.position;
        state_.position += direction * length;
        if (draw && length != 0.0) {
            Segment s;
            s.a = glm::vec3(start);
            s.b = glm::vec3(state_.position);
            s.ra = static_cast<float>(state_.width * 0.5);
            if (settings_.bend != 0.0)
                state_.width *= taper;
            else if (settings_.width_model == WidthModel::Taper)
                state_.width *= state_.depth == 0 ? settings_.trunk_taper : settings_.branch_taper;
            s.rb = static_cast<float>(state_.width * 0.5);
            s.parent = state_.parent;
            s.depth = state_.depth;
            s.color = state_.color;
            state_.parent = static_cast<int>(out_.segments.size());
            out_.segments.push_back(s);
            if (settings_.width_variation != 0.0) {
                span_branch_.push_back(state_.branch);
                span_start_.push_back(state_.arc);
                span_end_.push_back(state_.arc + std::abs(length));
            }
        }
        state_.arc += std::abs(length);
        if (last && settings_.mode == TurtleMode::Abop) apply_tropism();
    }

    glm::dvec3 lptg_direction() const {
        double e = state_.elevation * kDegree, a = state_.azimuth * kDegree;
        return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
    }

    // The tropism vector, varied along each branch by three noise channels.
    glm::dvec3 tropism() const {
        const double v = settings_.tropism_variation;
        if (v == 0.0) return settings_.tropism;
        const double s = state_.arc * settings_.bend_frequency;
        const double y = branch_coordinate(state_.branch);
        return settings_.tropism +
               v * glm::dvec3(tropism_[0](s, y), tropism_[1](s, y), tropism_[2](s, y));
    }

    void apply_tropism() {
        if (settings_.elasticity == 0.0) return;
        glm::dvec3 axis = glm::cross(state_.heading, tropism());
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

    // A polygon that marks vertices with '.' takes those (as they were marked); else its
    // traced outline.
    void close_polygon(size_t i) {
        if (polygons_.empty()) {
            if (positions_) return;
            throw GrammarError("the derived word has a '}' with no '{' (module " +
                               std::to_string(i + 1) + ")");
        }
        OpenPolygon& open = polygons_.back();
        std::vector<glm::vec3> outline =
            open.dotted.empty() ? clean_outline(open.traced) : std::move(open.dotted);
        if (outline.size() >= 3) {
            out_.polygons.push_back(std::move(outline));
            out_.polygon_colors.push_back(open.color);
        }
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
    NoiseField bend_pitch_, bend_turn_, width_;
    NoiseField tropism_[3];
    std::uint64_t jitter_seed_;
    std::vector<glm::vec3>* positions_;            // turtle_positions(): where each module is read
    std::array<std::string, kMaxWords> surfaces_;  // per word symbol: its organ, or empty
    int branches_ = 0;
    // Per drawn segment, for width variation: its branch and its span along the branch.
    std::vector<int> span_branch_;
    std::vector<double> span_start_, span_end_;
    State state_;
    std::vector<State> stack_;
    std::vector<OpenPolygon> polygons_;
    Skeleton out_;
};

}  // namespace

Skeleton interpret(const Word& word, const TurtleSettings& settings) {
    return Interpreter(word, settings).run();
}

void turtle_positions(const Word& word, const TurtleSettings& settings,
                      std::vector<glm::vec3>& positions) {
    TurtleSettings walk = settings;
    walk.progress = nullptr;
    walk.width_model = WidthModel::Explicit;  // widths are not wanted
    walk.width_variation = 0.0;
    Interpreter(word, walk, &positions).run();
}

}  // namespace sylva
