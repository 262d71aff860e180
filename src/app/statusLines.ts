import type { Catalogue } from '../i18n/en.ts';
import type { EnvironmentStatus } from '../view/drawnFrame.ts';
import { environmentStatusText } from './environmentStatusText.ts';

/**
 * The app's lines in the page's messages (role status; as text, never HTML): why the view draws
 * something else than was asked (the frame's notices that say so: another method, sRGB for a wide
 * space the canvas cannot show; src/view/drawnFrame.ts), and that the HDR environment
 * is loading or failed. A line is in the messages while it has something to say; without a
 * messages element none is shown.
 */
export class StatusLines {
  private readonly notices: HTMLElement;
  private readonly environment: HTMLElement;

  constructor(
    doc: Document,
    private readonly messages: HTMLElement | undefined,
    private readonly cat: Catalogue,
  ) {
    this.notices = Object.assign(doc.createElement('p'), { className: 'frame-notice' });
    this.environment = Object.assign(doc.createElement('p'), { className: 'environment-status' });
  }

  /** Says why the view draws something else than was asked (the frame's notices that say so), or removes the line (none). */
  showNotices(lines: readonly string[]): void {
    this.show(this.notices, lines.length > 0 ? lines.join(' ') : null);
  }

  /** Says that the HDR environment is loading or failed (the line's `data-state`), or removes the line once it shows. */
  showEnvironment(status: EnvironmentStatus): void {
    if (status.state === 'shown') {
      this.show(this.environment, null);
      return;
    }
    this.environment.dataset.state = status.state;
    this.show(this.environment, environmentStatusText(status, this.cat));
  }

  remove(): void {
    this.notices.remove();
    this.environment.remove();
  }

  private show(line: HTMLElement, text: string | null): void {
    if (text === null || !this.messages) {
      line.remove();
      return;
    }
    line.textContent = text;
    if (line.parentElement !== this.messages) this.messages.append(line);
  }
}
