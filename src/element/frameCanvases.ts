/**
 * The element's picture: each frame of the shared renderer copied into a 2-D canvas of the drawing
 * buffer's colour space, so a Display P3 frame keeps its colours outside sRGB instead of being
 * clipped on the way. A 2-D context's space is fixed when it is made: the element's own canvas
 * (sRGB) stays, as it takes focus, keys and presses (BubbleApp's `focusable`), and while the view
 * shows Display P3 a canvas of that space lies beneath it and takes the frames, the own canvas left
 * clear above it. An sRGB frame is copied into the own canvas, where it reads back unchanged.
 */
export class FrameCanvases {
  /** The Display P3 canvas, while the view shows Display P3. */
  private p3Canvas: HTMLCanvasElement | null = null;

  constructor(private readonly canvas: HTMLCanvasElement) {}

  /** Copies `frame` (the renderer's canvas) to the page, into a Display P3 canvas where `displayP3`. */
  show(frame: HTMLCanvasElement, displayP3: boolean): void {
    if (displayP3 !== (this.p3Canvas !== null)) this.setSpace(displayP3);
    const target = this.p3Canvas ?? this.canvas;
    const { width, height } = frame;
    if (target.width !== width || target.height !== height) Object.assign(target, { width, height });
    target.getContext('2d')?.drawImage(frame, 0, 0);
  }

  /** Adds the Display P3 canvas beneath the own one, which is cleared, or removes it. */
  private setSpace(displayP3: boolean): void {
    this.p3Canvas?.remove();
    this.p3Canvas = null;
    if (!displayP3) return;
    const canvas = this.canvas.ownerDocument.createElement('canvas');
    canvas.getContext('2d', { colorSpace: 'display-p3' }); // the space is taken at the first getContext
    canvas.setAttribute('aria-hidden', 'true'); // the own canvas above names the picture
    this.canvas.before(canvas);
    this.canvas.getContext('2d')?.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.p3Canvas = canvas;
  }
}
