// Growth method "dummy": what a growth method added from outside Sylva's own folders looks
// like. This folder and the one line in register.cpp are all it takes; the test beside it
// checks that its parameters reach `sylva --help`, --set, template files, skeleton.json and
// the studio's controls with no other edit. It grows `dummy_stems` straight stems of
// `dummy_height` meters, fanned out when `dummy_fan` is on.
#pragma once

#include "core/growth.h"

namespace sylva::dummy {

struct DummyParams {
    double height = 3.0;  // dummy_height
    int stems = 1;        // dummy_stems
    bool fan = false;     // dummy_fan
};

extern const GrowthMethod dummy_growth;

}  // namespace sylva::dummy
