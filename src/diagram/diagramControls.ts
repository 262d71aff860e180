import { FILM_STACK_DOMAIN, POLARIZATIONS, type Polarization } from '../physics/filmReflectance.ts';
import type { NumberDomain } from '../input/validate.ts';
import type { Catalogue, MessageKey } from '../i18n/en.ts';
import { type DiagramSettings, WAVELENGTH_DOMAIN } from './diagramParameters.ts';
import { settingText } from './numberText.ts';

/** The diagram's own controls: real, labelled inputs, each named after the attribute it sets. */
export interface DiagramControls {
  readonly element: HTMLElement;
  /** Shows these settings in the controls. */
  sync(settings: DiagramSettings, flipTop: boolean): void;
}

export const polarizationName = (p: Polarization | 's' | 'p' | 'paper', cat: Catalogue): string => cat[`common.polarization.${p}`];

/**
 * Builds the controls: thickness (a number field), θ_i and λ (sliders with their values shown),
 * the polarisation (a list) and the no-phase-flip toggle. `onValue` gets an attribute's name and
 * the text the user gave, to be read as that attribute is; `onFlip` the toggle's state.
 */
export function buildDiagramControls(
  doc: Document,
  cat: Catalogue,
  idPrefix: string,
  onValue: (attribute: string, raw: string) => void,
  onFlip: (on: boolean) => void,
): DiagramControls {
  const group = Object.assign(doc.createElement('div'), { className: 'tfd-controls' });
  group.setAttribute('role', 'group');
  group.setAttribute('aria-label', cat['diagram.controls']);
  const labelled = (key: MessageKey, control: HTMLInputElement | HTMLSelectElement, attribute: string, extra?: HTMLOutputElement) => {
    const label = doc.createElement('label');
    control.id = `${idPrefix}-${attribute}`;
    control.dataset.attribute = attribute;
    label.htmlFor = control.id;
    label.append(Object.assign(doc.createElement('span'), { textContent: cat[key] }), control);
    if (extra) {
      extra.htmlFor.add(control.id);
      label.append(extra);
    }
    group.append(label);
    control.addEventListener('input', () => onValue(attribute, control.value));
    return control;
  };
  const number = (type: 'number' | 'range', domain: NumberDomain, step: number) =>
    Object.assign(doc.createElement('input'), { type, min: String(domain.min), max: String(domain.max), step: String(step) });

  const thickness = labelled('common.thickness', number('number', FILM_STACK_DOMAIN.thicknessNm, 1), 'thickness');
  const angle = number('range', FILM_STACK_DOMAIN.angleDeg, 0.5);
  const angleOut = doc.createElement('output');
  labelled('common.angle', angle, 'angle', angleOut);
  const wavelength = number('range', WAVELENGTH_DOMAIN, 1);
  const wavelengthOut = doc.createElement('output');
  labelled('common.wavelength', wavelength, 'wavelength', wavelengthOut);
  const polarization = doc.createElement('select');
  for (const p of POLARIZATIONS)
    polarization.append(Object.assign(doc.createElement('option'), { value: p, textContent: polarizationName(p, cat) }));
  labelled('common.polarization', polarization, 'polarization');

  const flip = Object.assign(doc.createElement('input'), { type: 'checkbox', id: `${idPrefix}-flip` });
  const flipLabel = Object.assign(doc.createElement('label'), {
    className: 'tfd-check',
    htmlFor: flip.id,
    title: cat['diagram.flipTopHint'],
  });
  flipLabel.append(flip, Object.assign(doc.createElement('span'), { textContent: cat['diagram.flipTop'] }));
  flip.title = cat['diagram.flipTopHint'];
  flip.addEventListener('change', () => onFlip(flip.checked));
  group.append(flipLabel);

  return {
    element: group,
    sync(s, flipTop) {
      // A field being typed in keeps its text (it may be on its way to a valid number).
      if (doc.activeElement !== thickness) thickness.value = settingText(s.thicknessNm);
      angle.value = String(s.angleDeg);
      angleOut.textContent = `${settingText(s.angleDeg)}°`;
      wavelength.value = String(s.wavelengthNm);
      wavelengthOut.textContent = `${settingText(s.wavelengthNm)} nm`;
      polarization.value = s.polarization;
      flip.checked = flipTop;
    },
  };
}
