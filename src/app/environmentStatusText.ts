import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { EnvironmentStatus } from '../scene/bubbleView.ts';

/** The line a page shows while an HDR environment loads, or after it failed, in a catalogue's language. */
export const environmentStatusText = (status: Exclude<EnvironmentStatus, { state: 'shown' }>, cat: Catalogue = EN): string =>
  status.state === 'loading'
    ? message(cat, 'app.environmentLoading', { env: status.env })
    : message(cat, 'app.environmentFailed', { env: status.env, reason: status.reason });
