/**
 * The embeddable bubble as one ES module: `<script type="module" src=".../thin-film-bubble.js">`
 * defines `<thin-film-bubble>`; see README "Embedding".
 */
import { defineThinFilmBubble } from './thinFilmBubble.ts';

export { ThinFilmBubble, defineThinFilmBubble } from './thinFilmBubble.ts';
defineThinFilmBubble();
