// SPDX-License-Identifier: MIT
// OpenGL adapter, fragment stage of pipeline scenes (DRIVER.OPENGL.VALUES): ORs the coverage
// like opengl_coverage.frag and stores the attributes the shader sees, one plane of W x H x N
// floats per slot (W x H x S x N under sample-rate shading, S samples, the entry of
// gl_SampleID). The adapter replaces the marker comments below (inputs, entry, store).
// rule: DRIVER.OPENGL.VALUES
#version 430 core

//INPUTS
layout(location = 1) uniform uint slot0;
layout(location = 2) uniform uint width;
layout(location = 3) uniform uint height;
layout(location = 4) uniform uint slots;

layout(std430, binding = 0) buffer Coverage {
  uint mask[];
} coverage;

layout(std430, binding = 1) buffer Values {
  float values[];
};

void main() {
  uint x = uint(gl_FragCoord.x);
  uint y = uint(gl_FragCoord.y);
  uint slot = slot0 + uint(gl_PrimitiveID);
  if (x >= width || y >= height || slot >= slots) {
    return;
  }
  uint pixel = (slot * height + y) * width + x;
  atomicOr(coverage.mask[pixel], uint(gl_SampleMaskIn[0]));
  uint base = //ENTRY;
//STORE
}
