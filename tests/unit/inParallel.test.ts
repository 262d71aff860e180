import { describe, expect, it } from 'vitest';
import { type Finished, runInParallel } from '../../scripts/inParallel.ts';

const node = (code: string) => [process.execPath, '-e', code];

describe('runInParallel (npm test runs its checks that time nothing at once)', () => {
  it('runs the commands at once: a command that waits for a file the other writes ends', async () => {
    // Each side's output is kept whole, in the order it wrote; each is reported once, as it ends.
    const dir = `${process.env.TMPDIR ?? '/tmp'}/in-parallel-${process.pid}`;
    const waiter = node(
      `const fs=require('fs');process.stdout.write('a1 ');const t=setInterval(()=>{if(fs.existsSync('${dir}')){clearInterval(t);console.error('a2');fs.rmdirSync('${dir}')}},10)`,
    );
    const writer = node(`process.stdout.write('b1 ');require('fs').mkdirSync('${dir}');console.log('b2')`);
    const reported: Finished[] = [];
    expect(await runInParallel([waiter, writer], (f) => reported.push(f))).toBe(0);
    expect(reported.map((f) => [f.command, f.status, f.output]).sort()).toEqual([
      [waiter, 0, 'a1 a2\n'],
      [writer, 0, 'b1 b2\n'],
    ]);
  });

  it('exits with the first non-zero status in the order given, after every command ends', async () => {
    const reported: number[] = [];
    const status = await runInParallel([node('process.exit(0)'), node('process.exit(3)'), node('process.exit(5)')], (f) =>
      reported.push(f.status),
    );
    expect(status).toBe(3);
    expect(reported.sort()).toEqual([0, 3, 5]);
  });

  it('a command that cannot start fails with status 1 and says why', async () => {
    const reported: Finished[] = [];
    expect(await runInParallel([['/no/such/command']], (f) => reported.push(f))).toBe(1);
    expect(reported[0]!.output).toContain('ENOENT');
  });
});
