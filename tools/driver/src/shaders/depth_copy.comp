// SPDX-License-Identifier: MIT
// lavapipe adapter, the depth passes of pipeline scenes on multisampled targets
// (DRIVER.LAVAPIPE.VALUES): copies every sample of the multisampled depth attachment to the
// readback buffer as a float (texelFetch of a sampler2DMS): the stored float for D32F,
// k / 65535 rounded to float32 for D16.
// rule: DRIVER.LAVAPIPE.VALUES
#version 450

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2DMS depth_texture;

layout(std430, set = 0, binding = 1) buffer Out {
  float v[];
} out_;

layout(push_constant) uniform Push {
  uint width;
  uint height;
  uint samples;
  uint offset;  // first float of this slot and pass in the buffer
} push;

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= push.width || p.y >= push.height) {
    return;
  }
  for (uint q = 0u; q < push.samples; ++q) {
    out_.v[push.offset + (p.y * push.width + p.x) * push.samples + q] =
        texelFetch(depth_texture, ivec2(p), int(q)).r;
  }
}
