#include "core/wind_params.h"

namespace sylva {

const ParamTable& wind_param_table() {
    using W = WindParams;
    using enum ParamGroup;
    static const ParamTable table = ParamTable::owned<W>(
        "", {
                param("wind_strength", &W::strength, 0.0, 5.0, Wind,
                      "wind: metres the top of the tree leans in a steady wind (gusts swing it "
                      "between half and 1.5 times that)"),
                param("wind_direction", &W::direction, 0.0, 360.0, Wind,
                      "wind: where it blows to on the ground, degrees from +x towards +z"),
                param("wind_gust_frequency", &W::gust_frequency, 0.0, 5.0, Wind,
                      "wind: gusts per second, a smooth noise in time (0: a steady wind)"),
                param("wind_flutter", &W::flutter, 0.0, 1.0, Wind,
                      "wind: how far leaf tips flutter, as a share of wind_strength"),
            });
    return table;
}

}  // namespace sylva
