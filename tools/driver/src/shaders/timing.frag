// SPDX-License-Identifier: MIT
// lavapipe coverage timing, fragment stage: writes nothing (no attachment, no buffer); the
// occlusion query counts the covered samples (BENCH.LAVAPIPE). Used with coverage.vert.
// rule: BENCH.LAVAPIPE
#version 450

void main() {}
