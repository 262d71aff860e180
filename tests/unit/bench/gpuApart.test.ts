import { type ChildProcess, spawn } from 'node:child_process';
import { afterEach, describe, expect, it } from 'vitest';
import { allowedCores, gpuApartUnavailable, holdApart } from '../../../scripts/bench/gpuApart.ts';

describe.skipIf(gpuApartUnavailable() !== null)('holding a process apart (Linux, 2 cores or more)', () => {
  const children: ChildProcess[] = [];
  const sleeper = () => {
    const c = spawn('sleep', ['60']);
    children.push(c);
    return c.pid!;
  };
  afterEach(() => children.splice(0).forEach((c) => c.kill()));

  // The kernel's word on each child's cores (/proc/<pid>/status); a child starts with its parent's.
  it('puts the GPU on the last core and the others on the rest while measuring, then gives both their cores back', async () => {
    const [gpu, page] = [sleeper(), sleeper()];
    const cores = allowedCores(gpu);
    const during = await holdApart(gpu, [page], () => Promise.resolve([allowedCores(gpu), allowedCores(page)]));
    expect(during).toEqual([cores.slice(-1), cores.slice(0, -1)]);
    expect([allowedCores(gpu), allowedCores(page)]).toEqual([cores, cores]);
  });

  it('gives the cores back when the measurement fails', async () => {
    const gpu = sleeper();
    const cores = allowedCores(gpu);
    await expect(holdApart(gpu, [], () => Promise.reject(new Error('measured nothing')))).rejects.toThrow('measured nothing');
    expect(allowedCores(gpu)).toEqual(cores);
  });
});
