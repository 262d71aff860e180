import { chromium } from '@playwright/test';
const webgpu = process.argv[2] === 'webgpu';
const args = webgpu
  ? ['--enable-unsafe-webgpu', '--enable-features=Vulkan,VulkanFromANGLE,DefaultANGLEVulkan', '--use-angle=vulkan']
  : ['--use-gl=angle', '--use-angle=gles-egl', '--ignore-gpu-blocklist', '--disable-quic'];
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args });
const page = await browser.newPage();
page.on('console', (m) => console.log('console:', m.type(), m.text().slice(0, 2000)));
page.on('pageerror', (e) => console.log('pageerror:', e.message));
await page.goto('http://127.0.0.1:5312/tests/e2e/harness/webgpu.html');
await page.waitForFunction(() => document.body.dataset.ready === 'yes', null, { timeout: 120000 });
const script = process.argv[3];
const t0 = Date.now();
const out = await page.evaluate(script);
console.log(JSON.stringify(out), (Date.now() - t0) + ' ms');
await browser.close();
