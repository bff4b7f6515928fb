// SPDX-License-Identifier: MIT
// OpenGL adapter, vertex stage of pipeline scenes (DRIVER.OPENGL.VALUES): clip-space positions
// (after the scene's transform, computed on the CPU as the reference computes it) pass through;
// window-space ones are divided by K exactly and y negated exactly, as in opengl_coverage.vert.
// The adapter replaces the marker comments below (inputs, outputs, copy) with one line per
// attribute, with its interpolation and location qualifiers.
// rule: DRIVER.OPENGL.VALUES
#version 430 core

layout(location = 0) in vec4 pos;
//INPUTS
//OUTPUTS
layout(location = 0) uniform float inv_k;
layout(location = 5) uniform uint window_space;

void main() {
  if (window_space != 0u) {
    gl_Position = vec4(pos.x * inv_k, -(pos.y * inv_k), pos.z, 1.0);
  } else {
    gl_Position = pos;
  }
//COPY
}
