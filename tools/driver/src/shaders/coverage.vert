// SPDX-License-Identifier: MIT
// lavapipe adapter, vertex stage: window coordinates in, exact clip coordinates out.
// rule: DRIVER.LAVAPIPE.POSITION
#version 450

layout(location = 0) in vec2 window_pos;  // float32 window coordinates, exactly as read

layout(push_constant) uniform Push {
  float inv_k;   // 1 / K, K a power of two: the division is exact
  uint slot;     // first coverage slot of this draw (one per primitive, one per strip segment)
  uint width;
  uint height;
  uint slots;
} push;

void main() {
  gl_Position = vec4(window_pos * push.inv_k, 0.0, 1.0);
  gl_PointSize = 1.0;
}
