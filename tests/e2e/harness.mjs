// What the end-to-end tests share: a static server on 127.0.0.1 and Debian's Chromium through
// playwright-core, with the flags a headless run on a shared machine needs.
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';

/**
 * Serves `directory` on 127.0.0.1:`port` (Python's http.server) and waits until `page`
 * answers. Returns the base URL and a function that stops the server.
 */
export async function serve(directory, port, page) {
  const server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', directory],
    { stdio: 'ignore' });
  const base = `http://127.0.0.1:${port}`;
  for (let i = 0; ; i++) {
    try { await fetch(`${base}/${page}`); break; } catch (e) {
      if (i > 50) { server.kill(); throw e; }
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  return { base, stop: () => server.kill() };
}

/** Headless Chromium: `$CHROMIUM`, else Debian's /usr/bin/chromium. */
export function launchChromium() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run', '--disable-quic'],
  });
}
