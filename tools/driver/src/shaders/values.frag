// SPDX-License-Identifier: MIT
// lavapipe adapter, fragment stage of pipeline scenes (DRIVER.LAVAPIPE.VALUES): ORs the
// coverage like coverage.frag and stores, per attribute, the input of the interpolation the
// scene declares (push.kinds: 0 smooth, 1 noperspective, 2 flat, 3 centroid smooth,
// 4 centroid noperspective), one plane of W x H x count floats per slot.
// rule: DRIVER.LAVAPIPE.VALUES
#version 450

layout(push_constant) uniform Push {
  float inv_k;
  uint slot;
  uint width;
  uint height;
  uint slots;
  uint window_space;
  uint count;
  uint kinds[2];
  uint per_sample;
} push;

layout(std430, set = 0, binding = 0) buffer Coverage {
  uint mask[];
} coverage;

layout(std430, set = 0, binding = 1) buffer Values {
  float v[];
} values;

layout(location = 0) in vec4 a_smooth[4];
layout(location = 4) noperspective in vec4 a_linear[4];
layout(location = 8) flat in vec4 a_flat[4];
layout(location = 12) centroid in vec4 a_centroid[4];
layout(location = 16) centroid noperspective in vec4 a_centroid_linear[4];

void main() {
  uint x = uint(gl_FragCoord.x);
  uint y = uint(gl_FragCoord.y);
  uint slot = push.slot + uint(gl_PrimitiveID);
  if (x >= push.width || y >= push.height || slot >= push.slots) {
    return;
  }
  uint pixel = (slot * push.height + y) * push.width + x;
  atomicOr(coverage.mask[pixel], uint(gl_SampleMaskIn[0]));
  for (uint j = 0u; j < push.count && j < 16u; ++j) {
    uint kind = (push.kinds[j >> 3] >> (4u * (j & 7u))) & 15u;
    uint q = j >> 2;
    uint c = j & 3u;
    float a;
    if (kind == 0u) {
      a = a_smooth[q][c];
    } else if (kind == 1u) {
      a = a_linear[q][c];
    } else if (kind == 2u) {
      a = a_flat[q][c];
    } else if (kind == 3u) {
      a = a_centroid[q][c];
    } else {
      a = a_centroid_linear[q][c];
    }
    values.v[pixel * push.count + j] = a;
  }
}
