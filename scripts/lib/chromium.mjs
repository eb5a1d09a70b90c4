// One headless Chromium page for the browser checks (scripts/three-check/,
// scripts/playground-check/): Debian's chromium driven by playwright-core,
// in a throw-away profile, with no GPU, no background networking and no
// first-run work, so a check sees only the requests its page makes.
import { mkdtempSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';

/** Opens a page; `close()` ends the browser and removes its profile. */
export async function openPage(playwright, executablePath, name) {
  const profile = mkdtempSync(join(tmpdir(), `${name}-`));
  let browser;
  try {
    browser = await playwright.chromium.launchPersistentContext(profile, {
      executablePath,
      headless: true,
      args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
    });
  } catch (e) {
    rmSync(profile, { recursive: true, force: true });
    throw e;
  }
  const page = browser.pages()[0] || (await browser.newPage());
  const close = async () => {
    await browser.close();
    rmSync(profile, { recursive: true, force: true });
  };
  return { page, close };
}
