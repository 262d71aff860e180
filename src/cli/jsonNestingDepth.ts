/**
 * How deeply the arrays and objects of a JSON text nest: the largest number of `[`/`{` open at
 * once, brackets inside strings not counted. One linear pass with no recursion, so a text of
 * 100 000 nested brackets is measured, not parsed (a recursive parser or printer would run out of
 * stack on it). The text need not be valid JSON; the parser judges that afterwards.
 */
export function jsonNestingDepth(text: string): number {
  let depth = 0;
  let deepest = 0;
  let inString = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (inString) {
      if (c === '\\') i++;
      else if (c === '"') inString = false;
    } else if (c === '"') {
      inString = true;
    } else if (c === '[' || c === '{') {
      deepest = Math.max(deepest, ++depth);
    } else if (c === ']' || c === '}') {
      depth--;
    }
  }
  return deepest;
}
