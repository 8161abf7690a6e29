#include "ui/position_buffer.h"

namespace sylva::studio {

PositionBuffer::PositionBuffer() {
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &vertex_buffer_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
}

PositionBuffer::~PositionBuffer() {
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void PositionBuffer::upload(std::span<const glm::vec3> points) {
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(points.size_bytes()), points.data(),
                 GL_STATIC_DRAW);
    count_ = static_cast<GLsizei>(points.size());
}

void PositionBuffer::draw(GLenum mode) const {
    glBindVertexArray(vertex_array_);
    glDrawArrays(mode, 0, count_);
    glBindVertexArray(0);
}

}  // namespace sylva::studio
