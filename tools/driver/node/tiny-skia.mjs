// SPDX-License-Identifier: MIT
// tiny-skia as a rastrules external driver (spec/driver.md DRIVER.PATH.TINY_SKIA), through
// @resvg/resvg-js (resvg, whose renderer is tiny-skia, as a native Node module): each path
// primitive becomes an SVG of the target's size (viewBox 0 0 w h: one SVG unit is one pixel, y
// down) holding one <path> with the kernel's snapped points as exact decimals (scene.mjs), its
// fill-rule, an opaque fill, and shape-rendering "crispEdges" (tiny-skia fills without
// antialiasing) for coverage "samples" or "geometricPrecision" (with) for "area". It is rendered
// at scale 1 on a transparent pixmap and the alpha channel is read back. Run by rastrules as
// `node tiny-skia.mjs` (the "tiny-skia" driver), one process per scene.
// Implements: DRIVER.PATH.TINY_SKIA

import { DriverFailure, pathLibraryCapabilities, rawText, run } from './scene.mjs';

let Resvg = null; // loaded for the first draw only: the capabilities query needs no native module

// The pixmap is width * height * 4 bytes, and resvg-js copies it once to JavaScript.
const capabilities = pathLibraryCapabilities({
  maxTargetSide: 4096,
  aliased:
    'tiny-skia fill_path without anti_alias: pixel centres inside, edges in 26.6' +
    ' rounded half up (centres on left and top edges out)',
  antialiased: 'tiny-skia fill_path with anti_alias: supersampled 4 x 4, 8-bit alpha',
});

// SVG path data of the snapped path: absolute commands, every contour closed (PATH.CONTOUR.CLOSE).
function pathData(path) {
  let d = '';
  for (const contour of path.contours) {
    for (const { op, pts } of contour)
      d += op + pts.map(([x, y]) => ` ${rawText(x)} ${rawText(y)}`).join('') + ' ';
    d += 'Z ';
  }
  return d.trim();
}

// Draws one snapped path alone; returns its alpha, width * height bytes from the top row.
async function draw(path, width, height) {
  const alpha = new Uint8Array(width * height);
  if (path.contours.length === 0)
    return alpha;
  Resvg ??= (await import('@resvg/resvg-js')).Resvg;
  const svg =
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" ` +
    `viewBox="0 0 ${width} ${height}"><path d="${pathData(path)}" fill="#000000" ` +
    `fill-rule="${path.fillRule}" ` +
    `shape-rendering="${path.antialiased ? 'geometricPrecision' : 'crispEdges'}"/></svg>`;
  const image = new Resvg(svg, {
    fitTo: { mode: 'original' }, // scale 1: the SVG's width and height in pixels
    font: { loadSystemFonts: false }, // no text: skip scanning the system's fonts
    logLevel: 'error',
  }).render();
  if (image.width !== width || image.height !== height)
    throw new DriverFailure(`resvg rendered ${image.width}x${image.height}, not ${width}x${height}`);
  const rgba = image.pixels; // RGBA, premultiplied: the alpha byte is what tiny-skia stored
  for (let i = 0; i < alpha.length; ++i)
    alpha[i] = rgba[4 * i + 3];
  return alpha;
}

await run(capabilities, draw);
