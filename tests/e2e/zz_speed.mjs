import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
const PORT = 8127;
const root = fileURLToPath(new URL('../../', import.meta.url));
const server = spawn('python3', ['-m', 'http.server', String(PORT), '--bind', '127.0.0.1', '--directory', `${root}web`], { stdio: 'ignore' });
const base = `http://127.0.0.1:${PORT}`;
for (let i = 0; ; i++) { try { await fetch(`${base}/index.html`); break; } catch (e) { if (i > 50) throw e; await new Promise((r) => setTimeout(r, 100)); } }
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const page = await browser.newPage();
await page.goto(`${base}/index.html`);
await page.waitForFunction(() => window.bandnoise && window.bandnoise.ready, null, { timeout: 30000 });
for (const kind of ['perlin', 'simplex', 'cellular', 'wavelet', 'multiband', 'value-cubic', 'white']) {
  await page.selectOption('#kind', kind);
  const times = [];
  for (let i = 0; i < 12; i++) {
    await page.fill('#seed', String(i + 1));
    await page.dispatchEvent('#seed', 'input');
    await page.dispatchEvent('#seed', 'change');
    await page.waitForTimeout(60);
    const t = await page.textContent('#readout');
    times.push(parseFloat(t));
  }
  times.sort((a, b) => a - b);
  console.log(kind.padEnd(12), 'median ms per frame', times[6], 'min', times[0]);
}
await browser.close();
server.kill();
