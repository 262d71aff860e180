import { describe, expect, it } from 'vitest';
import { cAbs2 } from '../../../src/physics/complex.ts';
import {
  type FilmStack,
  POLARIZATIONS,
  filmOptics,
  filmReflectance,
  meanChannelReflectance,
  reflectanceAt,
} from '../../../src/physics/filmReflectance.ts';
import { fresnelCoefficients } from '../../../src/physics/fresnel.ts';
import { cosDeg, refractedCos } from '../../../src/physics/snell.ts';
import { ALGEBRAIC_TOL, CONTINUITY_TOL, FEW_OPERATIONS_TOL, GOLDEN_TOL, QUADRATURE_TOL, ROUNDING_TOL } from '../../tolerances.ts';

const stack = (over: Partial<FilmStack>): FilmStack => ({ nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 500, angleDeg: 0, ...over });

/** Single-interface reflectances straight from the textbook forms (Hecht), not from fresnel.ts. */
function bareInterface(n1: number, n2: number, angleDeg: number): { s: number; p: number } {
  const t = (angleDeg * Math.PI) / 180;
  const ci = Math.cos(t);
  const st = (n1 / n2) * Math.sin(t);
  if (st >= 1) return { s: 1, p: 1 };
  const ct = Math.sqrt(1 - st * st);
  return {
    s: ((n1 * ci - n2 * ct) / (n1 * ci + n2 * ct)) ** 2,
    p: ((n1 * ct - n2 * ci) / (n1 * ct + n2 * ci)) ** 2,
  };
}

describe('film reflectance, eqs (1)–(14)', () => {
  it('matches the golden value: n = 1.5 in air, d = 250 nm, λ = 555 nm, 0° → R = 0.1215919', () => {
    expect(Math.abs(filmReflectance(555, stack({ nFilm: 1.5, thicknessNm: 250 })) - 0.1215919)).toBeLessThan(GOLDEN_TOL);
  });

  it('matches the normal-incidence closed form of a lossless film', () => {
    // R = (r1² + r2² + 2 r1 r2 cos φ) / (1 + r1² r2² + 2 r1 r2 cos φ), r1 = (na−nb)/(na+nb), r2 = (nb−nc)/(nb+nc).
    for (const [na, nb, nc, d, l] of [
      [1, 1.33, 1, 377, 612],
      [1.2, 2.4, 1.6, 1234, 433],
      [1, 1.05, 3.9, 20000, 701],
    ] as const) {
      const r1 = (na - nb) / (na + nb),
        r2 = (nb - nc) / (nb + nc);
      const cos = Math.cos((4 * Math.PI * nb * d) / l);
      const expected = (r1 * r1 + r2 * r2 + 2 * r1 * r2 * cos) / (1 + r1 * r1 * r2 * r2 + 2 * r1 * r2 * cos);
      const got = filmReflectance(l, { nOutside: na, nFilm: nb, nInside: nc, thicknessNm: d, angleDeg: 0 });
      expect(Math.abs(got - expected)).toBeLessThan(ROUNDING_TOL);
    }
  });

  it('has its quarter-wave minimum ((na nc − nb²)/(na nc + nb²))²', () => {
    for (const [na, nb, nc] of [
      [1, 1.33, 1],
      [1, 1.38, 1.52],
      [1.33, 2.2, 1],
    ] as const) {
      const l = 550;
      const expected = ((na * nc - nb * nb) / (na * nc + nb * nb)) ** 2;
      const got = filmReflectance(l, { nOutside: na, nFilm: nb, nInside: nc, thicknessNm: l / (4 * nb), angleDeg: 0 });
      expect(Math.abs(got - expected)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it('tends to the bare outside|inside interface as the thickness goes to 0', () => {
    for (const angle of [0, 20, 55, 80]) {
      const bare = bareInterface(1.1, 1.7, angle);
      for (const thicknessNm of [0, 1e-7]) {
        const s = stack({ nOutside: 1.1, nFilm: 2.3, nInside: 1.7, thicknessNm, angleDeg: angle });
        expect(Math.abs(filmReflectance(500, s, 's') - bare.s)).toBeLessThan(1e-9);
        expect(Math.abs(filmReflectance(500, s, 'p') - bare.p)).toBeLessThan(1e-9);
      }
    }
  });

  it('is the single film|inside interface when the film has the outside index', () => {
    for (const angle of [0, 35, 70]) {
      const bare = bareInterface(1.4, 1.9, angle);
      const s = stack({ nOutside: 1.4, nFilm: 1.4, nInside: 1.9, thicknessNm: 812, angleDeg: angle });
      expect(Math.abs(filmReflectance(480, s, 's') - bare.s)).toBeLessThan(ALGEBRAIC_TOL);
      expect(Math.abs(filmReflectance(480, s, 'p') - bare.p)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it('has R_s = R_p at normal incidence', () => {
    for (const d of [0, 123, 4567]) {
      const s = stack({ nFilm: 1.7, nInside: 1.2, thicknessNm: d });
      expect(Math.abs(filmReflectance(520, s, 's') - filmReflectance(520, s, 'p'))).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it('in the paper mode is exactly 0 at normal incidence (eqs 4 and 6 cancel), and not elsewhere', () => {
    for (const d of [0, 250, 999]) expect(filmReflectance(555, stack({ thicknessNm: d }), 'paper')).toBe(0);
    const oblique = filmReflectance(555, stack({ angleDeg: 30 }), 'paper');
    expect(oblique).toBeGreaterThan(0);
    expect(oblique).toBeLessThan(0.1 * filmReflectance(555, stack({ angleDeg: 30 })));
  });
});

describe('Snell, Fresnel and the phase, eqs (1)–(12)', () => {
  it('obeys the Stokes relations r_ba = −r_ab and t_ab t_ba − r_ab r_ba = 1', () => {
    const cos = cosDeg(37);
    const ci = { re: cos, im: 0 };
    const cr = refractedCos(1.9, 1.2, cos);
    const ab = fresnelCoefficients(1.2, ci, 1.9, cr);
    const ba = fresnelCoefficients(1.9, cr, 1.2, ci);
    for (const [r1, r2, t1, t2] of [
      [ab.rs, ba.rs, ab.ts, ba.ts],
      [ab.rp, ba.rp, ab.tp, ba.tp],
    ] as const) {
      expect(Math.abs(r1.re + r2.re)).toBeLessThan(FEW_OPERATIONS_TOL);
      expect(Math.abs(t1.re * t2.re - r1.re * r2.re - 1)).toBeLessThan(FEW_OPERATIONS_TOL);
    }
  });

  it('gives |r| = 1 past the critical angle', () => {
    const cos = cosDeg(60);
    const c = fresnelCoefficients(1.5, { re: cos, im: 0 }, 1, refractedCos(1, 1.5, cos));
    expect(Math.abs(cAbs2(c.rs) - 1)).toBeLessThan(FEW_OPERATIONS_TOL);
    expect(Math.abs(cAbs2(c.rp) - 1)).toBeLessThan(FEW_OPERATIONS_TOL);
  });

  it("uses Δ = 2 n_b d cos θ_r, equal to the paper's eq (12) with θ_ro = θ_ri", () => {
    for (const [na, nb, d, angle] of [
      [1, 1.33, 500, 30],
      [1.2, 2.5, 1234, 75],
      [1, 1.05, 80, 5],
    ] as const) {
      const ti = (angle * Math.PI) / 180;
      const tr = Math.asin((na * Math.sin(ti)) / nb);
      const eq12 = nb * d * (2 / Math.cos(tr)) - na * d * (2 * Math.tan(tr)) * Math.sin(ti);
      const optics = filmOptics({ nOutside: na, nFilm: nb, nInside: 1, thicknessNm: d, angleDeg: angle });
      expect(Math.abs(optics.opticalPathNm.re / eq12 - 1)).toBeLessThan(ROUNDING_TOL);
    }
  });
});

describe('the closed-form mean of R over a phase window', () => {
  /** [φ0, half-width] pairs: narrow to wider than a whole fringe. */
  const PHASE_WINDOWS = [
    [9.3, 0.01],
    [17.1, 0.5],
    [100.2, 2],
    [40, 3.14159],
    [60, 10],
  ] as const;
  const numericMean = (optics: ReturnType<typeof filmOptics>, i: number, phi0: number, w: number) => {
    const c = optics.channels[i]!;
    const lambda = (phi: number) => (2 * Math.PI * optics.opticalPathNm.re) / phi;
    const one = { ...optics, channels: [c] };
    const n = 20000;
    let sum = 0;
    for (let k = 0; k < n; k++) sum += reflectanceAt(one, lambda(phi0 - w + (2 * w * (k + 0.5)) / n));
    return sum / n;
  };
  it('equals the numerical average of eq (14) over the window (midpoint rule, 20 000 points)', () => {
    const cases = [
      [stack({ angleDeg: 30 }), 'unpolarized'],
      [{ nOutside: 1, nFilm: 2.5, nInside: 1.2, thicknessNm: 500, angleDeg: 80 }, 'unpolarized'],
      [stack({ angleDeg: 30 }), 'paper'],
      [{ nOutside: 1.5, nFilm: 1.33, nInside: 1, thicknessNm: 500, angleDeg: 45 }, 's'],
      [stack({ angleDeg: 89.9 }), 's'],
    ] as const;
    for (const [s, pol] of cases) {
      const optics = filmOptics(s, pol);
      optics.channels.forEach((c, i) => {
        for (const [phi0, w] of PHASE_WINDOWS) {
          expect(Math.abs(meanChannelReflectance(c, phi0, w) - numericMean(optics, i, phi0, w))).toBeLessThan(QUADRATURE_TOL);
        }
      });
    }
  });
  it('equals an independent quadrature of eqs (5)–(14) written out here (real angles, s and p)', () => {
    // Fresnel amplitudes (5), (6), (9), (10) and the Airy sum (13)–(14), from the equations alone.
    const cosIn = (n: number, na: number, angleDeg: number) => Math.sqrt(1 - ((na * Math.sin((angleDeg * Math.PI) / 180)) / n) ** 2);
    const airyMean = (s: FilmStack, pol: 's' | 'p', phi0: number, w: number) => {
      const [na, nb, nc] = [s.nOutside, s.nFilm, s.nInside];
      const [ca, cb, cc] = [cosIn(na, na, s.angleDeg), cosIn(nb, na, s.angleDeg), cosIn(nc, na, s.angleDeg)];
      const r = (n1: number, c1: number, n2: number, c2: number) =>
        pol === 's' ? (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2) : (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2);
      const t = (n1: number, c1: number, n2: number, c2: number) =>
        pol === 's' ? (2 * n1 * c1) / (n1 * c1 + n2 * c2) : (2 * n1 * c1) / (n2 * c1 + n1 * c2);
      const [rab, rba, rbc] = [r(na, ca, nb, cb), r(nb, cb, na, ca), r(nb, cb, nc, cc)];
      const T = t(na, ca, nb, cb) * t(nb, cb, na, ca);
      const n = 40000; // Simpson's rule on |r(φ)|² over [φ0 − w, φ0 + w]
      const reflectance = (phi: number) => {
        // r = r_ab + T r_bc e^{iφ} / (1 − r_ba r_bc e^{iφ}), all coefficients real here
        const [cr, ci] = [Math.cos(phi), Math.sin(phi)];
        const [dr, di] = [1 - rba * rbc * cr, -rba * rbc * ci];
        const d2 = dr * dr + di * di;
        const [nr, ni] = [T * rbc * cr, T * rbc * ci];
        const re = rab + (nr * dr + ni * di) / d2;
        const im = (ni * dr - nr * di) / d2;
        return re * re + im * im;
      };
      const h = (2 * w) / n;
      let sum = reflectance(phi0 - w) + reflectance(phi0 + w);
      for (let k = 1; k < n; k++) sum += (k % 2 ? 4 : 2) * reflectance(phi0 - w + k * h);
      return (sum * h) / 3 / (2 * w);
    };
    const cases: [FilmStack, 's' | 'p'][] = [
      [stack({ angleDeg: 30 }), 's'],
      [stack({ angleDeg: 30 }), 'p'],
      [{ nOutside: 1, nFilm: 2.5, nInside: 1.2, thicknessNm: 500, angleDeg: 80 }, 'p'],
      [{ nOutside: 1.5, nFilm: 1.33, nInside: 1, thicknessNm: 500, angleDeg: 40 }, 's'],
      [stack({ angleDeg: 89 }), 's'],
    ];
    for (const [s, pol] of cases) {
      const channel = filmOptics(s, pol).channels[0]!;
      for (const [phi0, w] of PHASE_WINDOWS) {
        expect(
          Math.abs(meanChannelReflectance(channel, phi0, w) - airyMean(s, pol, phi0, w)),
          `${pol} ${s.angleDeg}° ${phi0}±${w}`,
        ).toBeLessThan(QUADRATURE_TOL);
      }
    }
  });
  it('is the point value for a zero-width window', () => {
    const optics = filmOptics(stack({ angleDeg: 20 }), 's');
    const phi = (2 * Math.PI * optics.opticalPathNm.re) / 500;
    expect(Math.abs(meanChannelReflectance(optics.channels[0]!, phi, 0) - reflectanceAt(optics, 500))).toBeLessThan(ROUNDING_TOL);
  });
});

describe('thickness 0', () => {
  it('is continuous in every polarisation mode, the paper mode following its own eq (13)', () => {
    const stacks: FilmStack[] = [
      { nOutside: 1.6, nFilm: 1.33, nInside: 1, thicknessNm: 0, angleDeg: 45 },
      { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 0, angleDeg: 30 },
      { nOutside: 1, nFilm: 2.5, nInside: 1.5, thicknessNm: 0, angleDeg: 70 },
      { nOutside: 1.5, nFilm: 1.33, nInside: 1.2, thicknessNm: 0, angleDeg: 60 }, // TIR in the film
    ];
    for (const s of stacks) {
      for (const pol of POLARIZATIONS) {
        for (const lambda of [400, 500, 700]) {
          const at0 = reflectanceAt(filmOptics(s, pol), lambda);
          const near = reflectanceAt(filmOptics({ ...s, thicknessNm: 1e-3 }, pol), lambda);
          expect(Math.abs(at0 - near), `${pol} ${JSON.stringify(s)} ${lambda} nm`).toBeLessThan(CONTINUITY_TOL);
        }
      }
    }
  });
});
