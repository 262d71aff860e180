import { XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import type { Catalogue, MessageKey } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import type { ProbeReading } from '../view/probe.ts';
import { type ColorName, colorName } from './colorName.ts';
import { probeColor } from './probeColor.ts';
import { FILM_FILLS, filmFill } from '../methods/filmFills.ts';
import { filmOptionAt } from '../methods/filmStacks.ts';

/** A colour's name in a catalogue's language ("dark blue", "暗い青"). */
export function colorNameText(name: ColorName, cat: Catalogue): string {
  const hue = cat[`colour.${name.hue}` as MessageKey];
  return name.tone ? message(cat, `colour.tone.${name.tone}`, { hue }) : hue;
}

/**
 * One sentence on the film at the probe, for a screen reader: where the probe is (per cent of
 * the view), the film's thickness and θ_i, and its reference colour (eqs 15–19) in sRGB as a name
 * and a hex, and the notes its fill adds (a stack's: that it is one); or that the probe is off the bubble (a null reading).
 */
export function probeDescription(s: FilmSettings, probe: readonly [number, number], reading: ProbeReading | null, cat: Catalogue): string {
  const [x, y] = probe.map((v) => Math.round(v * 100));
  if (!reading) return message(cat, 'bubble.offBubble', { x: x!, y: y! });
  const film = { ...filmOptionAt(s, reading.angleDeg), thicknessNm: reading.thicknessNm };
  const c = probeColor(film, s, XYZ_TO_LINEAR_SRGB, reading.renderedXyz);
  const sentence = message(cat, 'bubble.description', {
    x: x!,
    y: y!,
    thickness: Math.round(reading.thicknessNm),
    angle: reading.angleDeg.toFixed(1),
    colour: colorNameText(colorName(c.rgb8), cat),
    hex: c.hex,
  });
  const notes = FILM_FILLS[filmFill(s)].probeNotes(s).map((note) => message(cat, note.key, note.values));
  return [sentence, ...notes].join(' ');
}
