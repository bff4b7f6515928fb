// SPDX-License-Identifier: MIT
// One spelling per enumerator of every convention a scene names: the word spec/scene.md uses
// for it. to_string() returns it, the scene reader accepts it and the writer writes it, the
// command line parses it and the driver adapters print it, all from one table per enumeration
// (Names<E>, rastrules/name_table.hpp), declared next to the enumeration in the headers below,
// so that no two places can spell a value differently. The exact oracle keeps words of its own
// (independence); tests/names checks that they are these and that spec/scene.md uses them.
// Implements: SCENE.FORMAT.V1 (the enumeration words)
#pragma once

#include "rastrules/isa.hpp"
#include "rastrules/line.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"
