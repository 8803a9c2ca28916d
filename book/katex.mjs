// mdBook preprocessor: renders the chapters' TeX math ($...$ inline, $$...$$ display) to
// HTML with KaTeX at build time, so the pages show equations with no JavaScript and no
// network (the stylesheet and fonts are copied into the book by scripts/book-build.sh).
//
// mdBook calls `node book/katex.mjs supports <renderer>` (exit 0: yes), then pipes
// `[context, book]` as JSON on stdin and reads the book back on stdout.
//
// Skipped: fenced code blocks, inline code spans, HTML comments (the generated-table
// markers) and `\$`. A TeX error is rendered as KaTeX's red error element (the browser
// test fails on it) and reported on stderr with the chapter and the source.
import katex from "katex";
import { readFileSync } from "node:fs";

if (process.argv[2] === "supports") process.exit(0);

let errors = 0;

// Characters that Markdown would interpret inside inline HTML text, written as entities.
function protect(html) {
  return html
    .split(/(<[^>]*>)/)
    .map((part, i) =>
      i % 2 === 1
        ? part.replace(/\s*\n\s*/g, " ") // a newline (KaTeX's SVG paths) would end a table row
        : part.replace(/[\\`*_[\]{}()#+\-.!|~$'"<>]/g, (c) => `&#${c.charCodeAt(0)};`)
    )
    .join("");
}

function render(tex, displayMode, where) {
  const source = tex.replace(/\s*\n\s*/g, " ").trim();
  try {
    return katex.renderToString(source, { displayMode, throwOnError: true, output: "html" });
  } catch (e) {
    errors += 1;
    console.error(`katex: ${where}: ${e.message}`);
    return katex.renderToString(source, { displayMode, throwOnError: false, output: "html" });
  }
}

// Leading whitespace of the line that contains position i.
function indentAt(text, i) {
  const start = text.lastIndexOf("\n", i - 1) + 1;
  return /^[ \t]*/.exec(text.slice(start))[0];
}

export function renderMath(text, where) {
  let out = "";
  let i = 0;
  let atLineStart = true;
  while (i < text.length) {
    if (atLineStart) {
      const fence = /^[ \t]*(`{3,}|~{3,})[^\n]*\n?/.exec(text.slice(i));
      if (fence) {
        const marker = fence[1];
        const close = new RegExp(`\\n[ \\t]*${marker[0] === "`" ? "`" : "~"}{${marker.length},}[ \\t]*(\\n|$)`);
        const rest = text.slice(i + fence[0].length - 1);
        const m = close.exec(rest);
        const end = m ? i + fence[0].length - 1 + m.index + m[0].length : text.length;
        out += text.slice(i, end);
        i = end;
        atLineStart = text[i - 1] === "\n";
        continue;
      }
    }
    const c = text[i];
    atLineStart = c === "\n";
    if (text.startsWith("<!-- BEGIN generated:", i)) {
      // Generated tables are plain text: a statement's `<v>` is not an HTML tag.
      const end = text.indexOf("<!-- END -->", i);
      const stop = end < 0 ? text.length : end + "<!-- END -->".length;
      const open = text.indexOf("-->", i) + 3;
      out += text.slice(i, open) + text.slice(open, stop - 12).replace(/</g, "&lt;").replace(/>/g, "&gt;") + text.slice(stop - 12, stop);
      i = stop;
      continue;
    }
    if (text.startsWith("<!--", i)) {
      const end = text.indexOf("-->", i);
      const stop = end < 0 ? text.length : end + 3;
      out += text.slice(i, stop);
      i = stop;
      continue;
    }
    if (c === "\\" && text[i + 1] === "$") {
      out += "\\$";
      i += 2;
      continue;
    }
    if (c === "`") {
      const run = /^`+/.exec(text.slice(i))[0];
      const end = text.indexOf(run, i + run.length);
      const stop = end < 0 ? i + run.length : end + run.length;
      out += text.slice(i, stop);
      i = stop;
      continue;
    }
    if (text.startsWith("$$", i)) {
      const end = text.indexOf("$$", i + 2);
      if (end < 0) {
        out += c;
        i += 1;
        continue;
      }
      let tex = text.slice(i + 2, end);
      let stop = end + 2;
      // Punctuation right after the display closes the sentence inside the display.
      const tail = /^[ \t]*([.,;:])[ \t]*(?=\n|$)/.exec(text.slice(stop));
      if (tail) {
        tex += tail[1];
        stop += tail[0].length;
      }
      const indent = indentAt(text, i);
      out += `\n\n${indent}<div class="math-display">${protect(render(tex, true, where))}</div>\n\n${indent}`;
      i = stop;
      while (text[i] === " " || text[i] === "\t") i += 1;
      if (text[i] === "\n") i += 1;
      atLineStart = true;
      continue;
    }
    if (c === "$") {
      // Inline: $ not followed by a space, closed by a $ not preceded by a space, on
      // the same paragraph (no blank line in between).
      const m = /^\$(?!\s)((?:\\.|[^$\\])+?)(?<!\s)\$/.exec(text.slice(i));
      if (m && !/\n[ \t]*\n/.test(m[1])) {
        out += protect(render(m[1], false, where));
        i += m[0].length;
        continue;
      }
    }
    out += c;
    i += 1;
  }
  return out;
}

function walk(items, fn) {
  for (const item of items || []) {
    if (item && item.Chapter) {
      fn(item.Chapter);
      walk(item.Chapter.sub_items, fn);
    }
  }
}

const [, book] = JSON.parse(readFileSync(0, "utf8"));
walk(book.items ?? book.sections, (chapter) => {
  chapter.content = renderMath(chapter.content, chapter.path ?? chapter.name);
});
process.stdout.write(JSON.stringify(book));
if (errors > 0) console.error(`katex: ${errors} formula(s) failed to render`);
