// Renders a .glb in the walkthrough viewer with headless Chromium (Debian's, through
// puppeteer-core) and writes a PNG screenshot:
//   node scripts/viewer/screenshot.mjs FILE.glb OUT.png [WIDTH HEIGHT]
// Prints the viewer's figures as JSON; exits 1 when the model did not load or the centre
// of the picture is background (nothing drawn), 2 on bad arguments.
import fs from 'fs';
import path from 'path';
import puppeteer from 'puppeteer-core';
import { serve } from './serve.mjs';

const [model, out, width = '800', height = '450'] = process.argv.slice(2);
if (!model || !out || !fs.existsSync(model)) {
  console.error('usage: node screenshot.mjs FILE.glb OUT.png [WIDTH HEIGHT]');
  process.exit(2);
}
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const server = await serve(path.resolve(model));
const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  // No GPU here: WebGL through SwiftShader (Chromium >= 137 wants this flag for it).
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
});
let status = 1;
try {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.setViewport({ width: Number(width), height: Number(height) });
  await page.goto(`http://127.0.0.1:${server.address().port}/?model=model.glb`);
  await page.waitForFunction('window.viewerStats !== undefined', { timeout: 120000 });
  const stats = await page.evaluate('window.viewerStats');
  await page.screenshot({ path: out });
  console.log(JSON.stringify({ ...stats, errors }));
  status = !stats.error && errors.length === 0 && stats.centreLitFraction > 0.5 ? 0 : 1;
} finally {
  await browser.close();
  server.close();
}
process.exit(status);
