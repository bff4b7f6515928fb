// SPDX-License-Identifier: MIT
// lavapipe adapter, vertex stage of pipeline scenes (DRIVER.LAVAPIPE.VALUES): a clip-space
// position (after the scene's transform, computed on the CPU as the reference computes it) with
// y negated exactly, which makes Vulkan's viewport transform D3D's (PIPE.VIEWPORT.TRANSFORM); or
// a window-space position divided by K exactly, as in coverage.vert. Each of the 16 attributes
// leaves under every interpolation the fragment stages may read: smooth, noperspective, flat,
// the two centroid ones and (values_sample.frag only) the two sample ones.
// rule: DRIVER.LAVAPIPE.VALUES
#version 450

layout(location = 0) in vec4 pos;
layout(location = 1) in vec4 attr[4];

layout(push_constant) uniform Push {
  float inv_k;
  uint slot;
  uint width;
  uint height;
  uint slots;
  uint window_space;  // 1: pos is (x, y, z, 1) in window coordinates
  uint count;         // declared attributes
  uint kinds[2];      // 4 bits per attribute: the interpolation the fragment stage reads
  uint per_sample;    // samples per pixel in the values buffer: 1, or the count (sample rate)
} push;

layout(location = 0) out vec4 a_smooth[4];
layout(location = 4) noperspective out vec4 a_linear[4];
layout(location = 8) flat out vec4 a_flat[4];
layout(location = 12) centroid out vec4 a_centroid[4];
layout(location = 16) centroid noperspective out vec4 a_centroid_linear[4];
layout(location = 20) sample out vec4 a_sample[4];
layout(location = 24) sample noperspective out vec4 a_sample_linear[4];

void main() {
  if (push.window_space != 0u) {
    gl_Position = vec4(pos.x * push.inv_k, pos.y * push.inv_k, pos.z, 1.0);
  } else {
    gl_Position = vec4(pos.x, -pos.y, pos.z, pos.w);
  }
  gl_PointSize = 1.0;
  for (int i = 0; i < 4; ++i) {
    a_smooth[i] = attr[i];
    a_linear[i] = attr[i];
    a_flat[i] = attr[i];
    a_centroid[i] = attr[i];
    a_centroid_linear[i] = attr[i];
    a_sample[i] = attr[i];
    a_sample_linear[i] = attr[i];
  }
}
