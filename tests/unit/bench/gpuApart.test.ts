import { type ChildProcess, execFileSync, spawn } from 'node:child_process';
import { cpus } from 'node:os';
import { afterEach, describe, expect, it } from 'vitest';
import { gpuApartUnavailable, holdApart } from '../../../scripts/bench/gpuApart.ts';

/** A list of whole numbers, `from` to `to` - 1. */
const range = (from: number, to: number) => Array.from({ length: to - from }, (_, i) => from + i);

/** The cores a process may run on, as the kernel reports them (taskset's list form, "0,2-3", read out). */
const coresOf = (pid: number) =>
  execFileSync('taskset', ['-c', '-p', String(pid)])
    .toString()
    .trim()
    .split(': ')[1]!
    .split(',')
    .flatMap((part) => {
      const [from, to = from] = part.split('-').map(Number);
      return range(from!, to! + 1);
    });

describe.skipIf(gpuApartUnavailable() !== null)('holding a process apart (Linux, 2 cores or more)', () => {
  const children: ChildProcess[] = [];
  const sleeper = () => {
    const c = spawn('sleep', ['60']);
    children.push(c);
    return c.pid!;
  };
  afterEach(() => children.splice(0).forEach((c) => c.kill()));

  it('puts the GPU on the last core and the others on the rest while measuring, then gives both every core', async () => {
    const [gpu, page] = [sleeper(), sleeper()];
    const last = cpus().length - 1;
    const during = await holdApart(gpu, [page], () => Promise.resolve([coresOf(gpu), coresOf(page)]));
    expect(during).toEqual([[last], range(0, last)]);
    expect([coresOf(gpu), coresOf(page)]).toEqual([range(0, last + 1), range(0, last + 1)]);
  });

  it('gives every core back when the measurement fails', async () => {
    const gpu = sleeper();
    await expect(holdApart(gpu, [], () => Promise.reject(new Error('measured nothing')))).rejects.toThrow('measured nothing');
    expect(coresOf(gpu)).toEqual(range(0, cpus().length));
  });
});
