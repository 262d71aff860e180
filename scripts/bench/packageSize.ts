/** The library's package as `npm pack` makes it: built as prepack builds it, then measured without writing a tarball. */
import { execFileSync } from 'node:child_process';

export interface PackageSize {
  /** the tarball's bytes (gzipped tar) */
  readonly tarballBytes: number;
  /** the bytes of the files it holds */
  readonly unpackedBytes: number;
  readonly files: number;
}

const npm = (args: readonly string[]) => execFileSync('npm', args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });

export function packageSize(): PackageSize {
  // What prepack runs, apart, so that pack's --json output is alone on stdout.
  npm(['run', '--silent', 'build:lib']);
  const [packed] = JSON.parse(npm(['pack', '--dry-run', '--json', '--ignore-scripts'])) as {
    size: number;
    unpackedSize: number;
    entryCount: number;
  }[];
  if (!packed) throw new Error('npm pack --dry-run --json printed no package');
  return { tarballBytes: packed.size, unpackedBytes: packed.unpackedSize, files: packed.entryCount };
}
