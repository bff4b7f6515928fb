// SPDX-License-Identifier: MIT
// OpenGL adapter, fragment stage: ORs the fragment's sample coverage into the coverage buffer,
// one W x H plane of 32-bit masks per slot (scene primitive or strip segment).
// rule: DRIVER.OPENGL.COVERAGE
#version 430 core

layout(location = 1) uniform uint slot0;   // first slot of this draw
layout(location = 2) uniform uint width;
layout(location = 3) uniform uint height;
layout(location = 4) uniform uint slots;   // number of slots of the whole scene

layout(std430, binding = 0) buffer Coverage {
  uint mask[];
} coverage;

void main() {
  uint x = uint(gl_FragCoord.x);
  uint y = uint(gl_FragCoord.y);
  // gl_PrimitiveID counts primitives within the draw: 0 for a triangle, point or line, the
  // segment index for a line strip (each scene primitive is its own draw).
  uint slot = slot0 + uint(gl_PrimitiveID);
  if (x >= width || y >= height || slot >= slots) {
    return;  // the framebuffer bounds discard these; never write outside the buffer
  }
  atomicOr(coverage.mask[(slot * height + y) * width + x], uint(gl_SampleMaskIn[0]));
}
