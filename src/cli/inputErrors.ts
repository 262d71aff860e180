import { shorten } from '../input/validate.ts';

/** A file path as it appears in an error message: quoted, cut only when absurd. */
export const describePath = (path: string): string => shorten(JSON.stringify(path), 200);
