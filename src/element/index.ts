/**
 * The embeddable bubble as one ES module: `<script type="module" src=".../thin-film-bubble.js">`
 * defines `<thin-film-bubble>` and `<thin-film-diagram>`; see docs/demo.md#embedding-thin-film-bubble and docs/diagram.md.
 */
import { defineThinFilmDiagram } from '../diagram/thinFilmDiagram.ts';
import { defineThinFilmBubble } from './thinFilmBubble.ts';

export { ThinFilmBubble, defineThinFilmBubble } from './thinFilmBubble.ts';
export type { ProbedFilm } from '../view/probe.ts';
export { ThinFilmDiagram, defineThinFilmDiagram } from '../diagram/thinFilmDiagram.ts';
defineThinFilmBubble();
defineThinFilmDiagram();
