import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { EnvironmentStatus } from '../view/drawnFrame.ts';
import { choiceKey } from '../settings/parameterRow.ts';

/** The line a page shows while an HDR environment loads, or after it failed, in a catalogue's language. */
export function environmentStatusText(status: Exclude<EnvironmentStatus, { state: 'shown' }>, cat: Catalogue = EN): string {
  const env = cat[choiceKey('env', status.env)];
  return status.state === 'loading'
    ? message(cat, 'app.environmentLoading', { env })
    : message(cat, 'app.environmentFailed', { env, reason: status.reason });
}
