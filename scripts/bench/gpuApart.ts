/**
 * A browser's GPU process held to a core of its own while a measurement runs, its pages' renderers
 * to the other cores (Linux's `taskset`). On a CPU rasteriser the GPU process's threads draw on
 * every core, and a page's task that overlaps a frame being drawn lasts as long as the scheduler
 * keeps the page's thread waiting for a core. Apart, a task's wall time is again the page's own
 * work, as beside a GPU, which draws on a device of its own.
 */
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { platform } from 'node:os';
import type { Browser } from '@playwright/test';

/** The cores process `pid` (this one unless given) may run on, in order: Linux's Cpus_allowed_list ("0-3,6") read out. */
export function allowedCores(pid: number | 'self' = 'self'): number[] {
  const list = /^Cpus_allowed_list:\s*(\S+)$/m.exec(readFileSync(`/proc/${pid}/status`, 'utf8'))?.[1] ?? '';
  return list.split(',').flatMap((part) => {
    const [from, to = from] = part.split('-').map(Number);
    return Array.from({ length: to! - from! + 1 }, (_, k) => from! + k);
  });
}

/** A process's every thread allowed only on `cores`. */
const allow = (pid: number, cores: readonly number[]) =>
  execFileSync('taskset', ['-a', '-p', '-c', cores.join(','), String(pid)], { stdio: 'ignore' });

/** Why the GPU process cannot be held apart here, or null where it can. */
export function gpuApartUnavailable(): string | null {
  if (platform() !== 'linux') return `holding the GPU process apart needs Linux's taskset, not ${platform()}`;
  const cores = allowedCores();
  if (cores.length < 2) return `holding the GPU process apart needs 2 cores or more, not ${cores.length}`;
  try {
    allow(process.pid, cores);
  } catch {
    return "holding the GPU process apart needs taskset (util-linux) and leave to set a process's cores, not found here";
  }
  return null;
}

/**
 * Runs `measure` with process `gpu` on the last of this process's cores and `others` on the rest,
 * then gives them all those cores again. Where gpuApartUnavailable() gives a reason, it is an error.
 */
export async function holdApart<T>(gpu: number, others: readonly number[], measure: () => Promise<T>): Promise<T> {
  const unavailable = gpuApartUnavailable();
  if (unavailable) throw new Error(unavailable);
  const cores = allowedCores();
  try {
    allow(gpu, cores.slice(-1));
    for (const pid of others) allow(pid, cores.slice(0, -1));
    return await measure();
  } finally {
    for (const pid of [gpu, ...others]) {
      try {
        allow(pid, cores);
      } catch {
        // a renderer closed meanwhile has no threads left to give cores to
      }
    }
  }
}

/** Runs `measure` with `browser`'s GPU process held apart from its renderers (holdApart). */
export async function withGpuApart<T>(browser: Browser, measure: () => Promise<T>): Promise<T> {
  const cdp = await browser.newBrowserCDPSession();
  const { processInfo } = (await cdp.send('SystemInfo.getProcessInfo')) as { processInfo: { type: string; id: number }[] };
  await cdp.detach();
  const gpu = processInfo.filter((p) => p.type === 'GPU').map((p) => p.id);
  const renderers = processInfo.filter((p) => p.type === 'renderer').map((p) => p.id);
  if (gpu.length !== 1 || renderers.length === 0)
    throw new Error(`the browser has ${gpu.length} GPU processes and ${renderers.length} renderers: cannot hold the GPU process apart`);
  return holdApart(gpu[0]!, renderers, measure);
}
