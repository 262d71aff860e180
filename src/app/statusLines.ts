import type { Catalogue } from '../i18n/en.ts';
import type { EnvironmentStatus } from '../view/drawnFrame.ts';
import { environmentStatusText } from './environmentStatusText.ts';

/**
 * The app's lines in the page's messages (role status; as text, never HTML): that the view draws
 * with another method than the one asked for (the frame's notice: src/view/drawnFrame.ts), and that the HDR environment
 * is loading or failed. A line is in the messages while it has something to say; without a
 * messages element none is shown.
 */
export class StatusLines {
  private readonly method: HTMLElement;
  private readonly environment: HTMLElement;

  constructor(
    doc: Document,
    private readonly messages: HTMLElement | undefined,
    private readonly cat: Catalogue,
  ) {
    this.method = Object.assign(doc.createElement('p'), { className: 'method-notice' });
    this.environment = Object.assign(doc.createElement('p'), { className: 'environment-status' });
  }

  /** Says why the view draws with another method (the frame's notice), or removes the line (null). */
  showMethodNotice(notice: string | null): void {
    this.show(this.method, notice);
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
    this.method.remove();
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
