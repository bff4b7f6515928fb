// SPDX-License-Identifier: MIT
// Skia as a rastrules external driver (spec/driver.md DRIVER.PATH.SKIA), through canvaskit-wasm
// (Skia compiled to WebAssembly, its CPU raster backend): each path primitive is built with a
// PathBuilder from the kernel's snapped points (scene.mjs), filled alone with an opaque paint on
// a cleared raster surface of the target, aliased (setAntiAlias(false)) for coverage "samples"
// and antialiased for "area", and the alpha channel is read back. Run by rastrules as
// `node skia.mjs` (the "skia" driver), one process per scene.
// Implements: DRIVER.PATH.SKIA

import { DriverFailure, pathLibraryCapabilities, run } from './scene.mjs';

// A raster surface is width * height * 4 bytes of WebAssembly memory.
const capabilities = pathLibraryCapabilities({
  maxTargetSide: 4096,
  aliased:
    'SkScan non-antialiased fill: pixel centres inside, edges in 26.6 (SkEdge)' +
    ' rounded half up (centres on left and top edges out)',
  antialiased: 'SkScan antialiased fill: analytic coverage (SkScan_AAAPath), 8-bit alpha',
});

let ck = null; // CanvasKit, loaded once per process (only for a draw: the query needs none)
let surface = null; // the raster surface of the current target
let paint = null;

// Draws one snapped path alone; returns its alpha, width * height bytes from the top row.
async function draw(path, width, height) {
  if (ck === null) {
    // Imported here, not at the top: the capabilities query then loads neither the module nor
    // its WebAssembly.
    const { default: CanvasKitInit } = await import('canvaskit-wasm');
    ck = await CanvasKitInit();
    paint = new ck.Paint();
    paint.setColor(ck.BLACK); // opaque: the stored alpha is the coverage
    paint.setStyle(ck.PaintStyle.Fill);
  }
  if (surface === null || surface.width() !== width || surface.height() !== height) {
    surface?.delete();
    surface = ck.MakeSurface(width, height); // a CPU raster surface (N32, premultiplied)
    if (surface === null)
      throw new DriverFailure(`canvaskit could not make a ${width}x${height} raster surface`);
  }
  const canvas = surface.getCanvas();
  canvas.clear(ck.TRANSPARENT);
  const builder = new ck.PathBuilder();
  const px = (raw) => raw / 256; // exact: |raw| <= 2^23 fits a float32's 24 bits
  for (const contour of path.contours) {
    for (const { op, pts } of contour) {
      const xy = pts.flatMap(([x, y]) => [px(x), px(y)]);
      if (op === 'M')
        builder.moveTo(...xy);
      else if (op === 'L')
        builder.lineTo(...xy);
      else if (op === 'Q')
        builder.quadTo(...xy);
      else
        builder.cubicTo(...xy);
    }
    builder.close(); // every contour is closed for filling (PATH.CONTOUR.CLOSE)
  }
  builder.setFillType(path.fillRule === 'evenodd' ? ck.FillType.EvenOdd : ck.FillType.Winding);
  const skPath = builder.detachAndDelete();
  paint.setAntiAlias(path.antialiased);
  canvas.drawPath(skPath, paint);
  skPath.delete();
  // Premultiplied RGBA: the alpha byte is what Skia stored, whatever the colour.
  const rgba = canvas.readPixels(0, 0, {
    width,
    height,
    colorType: ck.ColorType.RGBA_8888,
    alphaType: ck.AlphaType.Premul,
    colorSpace: ck.ColorSpace.SRGB,
  });
  if (!rgba || rgba.length !== width * height * 4)
    throw new DriverFailure('canvaskit: readPixels failed');
  const alpha = new Uint8Array(width * height);
  for (let i = 0; i < alpha.length; ++i)
    alpha[i] = rgba[4 * i + 3];
  return alpha;
}

await run(capabilities, draw);
