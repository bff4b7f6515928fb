// SPDX-License-Identifier: MIT
// lavapipe adapter, fragment stage: ORs the fragment's sample coverage into the coverage
// buffer, one W x H plane of 32-bit masks per slot (scene primitive or strip segment).
// rule: DRIVER.LAVAPIPE.COVERAGE
#version 450

layout(push_constant) uniform Push {
  float inv_k;
  uint slot;
  uint width;
  uint height;
  uint slots;    // number of slots of the whole scene
} push;

layout(std430, set = 0, binding = 0) buffer Coverage {
  uint mask[];
} coverage;

void main() {
  uint x = uint(gl_FragCoord.x);
  uint y = uint(gl_FragCoord.y);
  // gl_PrimitiveID counts primitives within the draw: 0 for a triangle, point or line, the
  // segment index for a line strip (each scene primitive is its own draw).
  uint slot = push.slot + uint(gl_PrimitiveID);
  if (x >= push.width || y >= push.height || slot >= push.slots) {
    return;  // the scissor discards these; never write outside the buffer
  }
  atomicOr(coverage.mask[(slot * push.height + y) * push.width + x], uint(gl_SampleMaskIn[0]));
}
