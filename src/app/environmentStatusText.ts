import type { EnvironmentStatus } from '../scene/bubbleView.ts';

/** The line a page shows while an HDR environment loads, or after it failed. */
export const environmentStatusText = (status: Exclude<EnvironmentStatus, { state: 'shown' }>): string =>
  status.state === 'loading'
    ? `Loading the environment ${status.env}…`
    : `The environment ${status.env} could not be loaded (${status.reason}): showing the sky instead.`;
