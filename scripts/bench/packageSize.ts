/** The library's package as `npm pack` makes it: built as prepack builds it, then measured without writing a tarball. */
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';

export interface PackageSize {
  /** the tarball's bytes (gzipped tar) */
  readonly tarballBytes: number;
  /** the bytes of the files it holds */
  readonly unpackedBytes: number;
  readonly files: number;
}

/**
 * npm's stdout; its stderr passed on. Asynchronous, so that the stages running meanwhile (pages
 * driven from this process) are not held up while it builds.
 */
async function npm(args: readonly string[]): Promise<string> {
  const child = promisify(execFile)('npm', args, { encoding: 'utf8' });
  child.child.stderr?.pipe(process.stderr);
  return (await child).stdout;
}

export async function packageSize(): Promise<PackageSize> {
  // What prepack runs, apart, so that pack's --json output is alone on stdout.
  await npm(['run', '--silent', 'build:lib']);
  const [packed] = JSON.parse(await npm(['pack', '--dry-run', '--json', '--ignore-scripts'])) as {
    size: number;
    unpackedSize: number;
    entryCount: number;
  }[];
  if (!packed) throw new Error('npm pack --dry-run --json printed no package');
  return { tarballBytes: packed.size, unpackedBytes: packed.unpackedSize, files: packed.entryCount };
}
