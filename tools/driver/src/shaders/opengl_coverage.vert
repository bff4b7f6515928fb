// SPDX-License-Identifier: MIT
// OpenGL adapter, vertex stage: window coordinates in, exact clip coordinates out. With
// glClipControl(GL_UPPER_LEFT, ...) the viewport transform negates y_ndc, so y is negated here
// (exactly) and y_window = y.
// rule: DRIVER.OPENGL.POSITION
#version 430 core

layout(location = 0) in vec2 window_pos;  // float32 window coordinates, exactly as read
layout(location = 0) uniform float inv_k;  // 1 / K, K a power of two: the product is exact

void main() {
  gl_Position = vec4(window_pos.x * inv_k, -(window_pos.y * inv_k), 0.0, 1.0);
}
