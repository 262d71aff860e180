/**
 * The embeddable bubble as one ES module: `<script type="module" src=".../thin-film-bubble.js">`
 * defines `<thin-film-bubble>` and `<thin-film-diagram>`; see README "Embedding" and docs/diagram.md.
 */
import { defineThinFilmDiagram } from '../diagram/thinFilmDiagram.ts';
import { defineThinFilmBubble } from './thinFilmBubble.ts';

export { ThinFilmBubble, type ProbedFilm, defineThinFilmBubble } from './thinFilmBubble.ts';
export { ThinFilmDiagram, defineThinFilmDiagram } from '../diagram/thinFilmDiagram.ts';
defineThinFilmBubble();
defineThinFilmDiagram();
