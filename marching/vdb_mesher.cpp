#include "marching/vdb_mesher.h"

#include <stdexcept>

namespace sylva {

Mesh vdb_mesh(const BatchField&, const Box&, const MarchingCubesSettings&, const VdbSettings&) {
    throw std::logic_error("vdb_mesh: not written yet");
}

}  // namespace sylva
