/**
 * A generated block of a Markdown file: the lines between `<!-- name -->` and `<!-- /name -->`.
 * The docs scripts write it; a unit test checks that the file holds exactly what they would write.
 */
export function withBlock(text: string, name: string, content: string): string {
  const open = `<!-- ${name} -->`;
  const close = `<!-- /${name} -->`;
  const start = text.indexOf(open);
  const end = text.indexOf(close);
  if (start < 0 || end < start) throw new Error(`the text has no ${open} … ${close} block`);
  return `${text.slice(0, start + open.length)}\n${content}\n${text.slice(end)}`;
}
