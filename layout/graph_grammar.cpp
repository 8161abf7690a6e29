#include "layout/graph_grammar.h"

namespace sylva::layout {

Boundary piece_boundary(const Piece& piece, const Directions& dirs) {
    if (piece.floating) {
        Boundary b(2);
        b[0].label = piece.edge;  // the head end, pointing out along the edge
        b[0].dart = 0;
        b[1].label = reversed(piece.edge, dirs);
        b[1].dart = 1;
        b[0].turn = b[1].turn = 180.0;
        set_wraps(b, dirs);
        return b;
    }
    return analyze(piece.graph, dirs).boundary;
}

}  // namespace sylva::layout
