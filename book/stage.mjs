// Stages the book's source into target/book-src/ (the `src` of book.toml): the course text
// (chapters/*.md), the summary (book/SUMMARY.md) and one page per repository file the
// text names.
//
// Links to the repository. The chapters name files of the repository (`src/...`,
// `docs/...`, `tests/...`, `benches/...`, `examples/...`) in code spans, in plain text or as
// Markdown links to `../src/...`. The book must work where it is read: on a machine with
// no network, and without knowing where the repository is hosted. So every named file
// becomes a page of the book, `code/<path>.md`, holding the file as it was when the book
// was built (in a code block), and every mention of the path links to that page; a
// named folder becomes a page listing its files. The pages are listed under "Source
// files" at the end of the summary (folded in the sidebar).
//
// Usage: node book/stage.mjs <repository root> <staging folder>
import { existsSync, mkdirSync, readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { dirname, extname, join, posix } from "node:path";

const [root, out] = process.argv.slice(2);
const PREFIX = "(?:src|docs|tests|benches|examples)/";
// A repository path: a prefix, then path characters, ending in a name character or `/`.
const PATH = new RegExp(`${PREFIX}[A-Za-z0-9_./-]*[A-Za-z0-9_/]`, "g");
const LANG = { ".rs": "rust", ".md": "markdown", ".py": "python", ".toml": "toml", ".m": "matlab", ".sh": "sh", ".json": "json" };

const pages = new Map(); // repository path -> page path (relative to the staging folder)

function pageFor(path) {
  const clean = path.replace(/\/+$/, "");
  const full = join(root, clean);
  if (!existsSync(full)) return null;
  const isDir = statSync(full).isDirectory();
  const page = isDir ? `code/${clean}/index.md` : `code/${clean}.md`;
  pages.set(clean + (isDir ? "/" : ""), page);
  return page;
}

// `text` (one chapter) with every repository path linked to its page. Fenced code blocks,
// math and the targets of existing links are left alone.
function linkPaths(text, fromDir) {
  const rel = (page) => posix.relative(fromDir, page);
  const parts = text.split(/(^```[^\n]*\n[\s\S]*?^```[^\n]*$)/m);
  return parts
    .map((part, i) => {
      if (i % 2 === 1) return part; // a fenced block
      // Existing links to repository files: `[text](../src/x.rs)`.
      part = part.replace(new RegExp(`\\]\\((?:\\.\\./)+(${PREFIX}[^)#\\s]*)\\)`, "g"), (m, p) => {
        const page = pageFor(p);
        return page ? `](${rel(page)})` : m;
      });
      // Code spans that are exactly a path: `src/physics/rigid.rs`.
      part = part.replace(/(\[?)`([^`\n]+)`/g, (m, open, code) => {
        if (open) return m; // already the text of a link
        if (!new RegExp(`^${PREFIX}`).test(code) || /\s/.test(code)) return m;
        const page = pageFor(code);
        return page ? `[\`${code}\`](${rel(page)})` : m;
      });
      // Plain-text paths (generated tables): only outside code spans, links and math.
      return part
        .split(/(`[^`\n]+`|\$\$[\s\S]*?\$\$|\$[^$\n]+\$|\]\([^)]*\)|\[[^\]\n]*\]\([^)]*\))/)
        .map((seg, j) => {
          if (j % 2 === 1) return seg;
          return seg.replace(PATH, (p, at, whole) => {
            const before = whole[at - 1] ?? " ";
            if (/[A-Za-z0-9_./-]/.test(before)) return p;
            const trail = p.match(/[.]+$/)?.[0] ?? "";
            const path = p.slice(0, p.length - trail.length);
            const page = pageFor(path);
            return page ? `[${path}](${rel(page)})${trail}` : p;
          });
        })
        .join("");
    })
    .join("");
}

// The page of one file: the file in a fenced block whose fence is longer than any run of
// backticks inside it; `{{#` escaped so that mdBook's include preprocessor leaves it.
function filePage(path) {
  const text = readFileSync(join(root, path), "utf8").replace(/\{\{#/g, "\\{{#");
  const longest = Math.max(2, ...(text.match(/`+/g) ?? [""]).map((r) => r.length));
  const fence = "`".repeat(longest + 1);
  // `noplayground`: mdBook would otherwise offer to run Rust files on the (online) playground.
  const lang = LANG[extname(path)] === "rust" ? "rust,noplayground" : LANG[extname(path)] ?? "text";
  return `# \`${path}\`\n\nThis file of the workbook's repository, as it was when this book was built.\n\n${fence}${lang}\n${text.replace(/\n?$/, "\n")}${fence}\n`;
}

function folderPage(path) {
  const entries = readdirSync(join(root, path), { withFileTypes: true })
    .filter((e) => !e.name.startsWith("."))
    .sort((a, b) => a.name.localeCompare(b.name));
  const lines = entries.map((e) => {
    const child = `${path}/${e.name}`;
    const page = e.isDirectory() ? `code/${child}/index.md` : `code/${child}.md`;
    pages.set(child + (e.isDirectory() ? "/" : ""), page);
    return `- [\`${child}${e.isDirectory() ? "/" : ""}\`](${posix.relative(`code/${path}`, page)})`;
  });
  return `# \`${path}/\`\n\nThis folder of the workbook's repository, as it was when this book was built.\n\n${lines.join("\n")}\n`;
}

// A table row with more unescaped `|` than its header loses its last cells silently (a
// tolerance "|x| <= 1" once showed as an empty cell): the build fails instead.
function checkTables(text, name) {
  const bad = [];
  const lines = text.split("\n");
  let header = -1;
  lines.forEach((line, i) => {
    if (!line.startsWith("|")) return void (header = -1);
    const pipes = (line.match(/(?<!\\)\|/g) ?? []).length;
    if (header < 0) header = pipes;
    else if (pipes !== header) bad.push(`${name}:${i + 1}: ${pipes - 1} cells in a table of ${header - 1} columns (an unescaped |?)`);
  });
  return bad;
}

// The preface is the book's front page: mdBook copies the first page to index.html at the
// book's top, where the preface's relative links must also resolve. So it is staged at
// the top (chapters/preface.md -> preface.md), its links moved up one level, and the
// chapters' links to it moved down.
mkdirSync(join(out, "chapters"), { recursive: true });
for (const f of readdirSync(join(root, "chapters")).sort()) {
  if (!f.endsWith(".md")) continue;
  const text = readFileSync(join(root, "chapters", f), "utf8");
  const bad = checkTables(text, `chapters/${f}`);
  if (bad.length > 0) {
    console.error(bad.join("\n"));
    process.exit(1);
  }
  if (f === "preface.md") {
    const up = text
      .replace(/\]\(\.\.\//g, "](")
      .replace(/\]\((?![a-z]+:|#|\/)([^)]*\.md(?:#[^)]*)?)\)/g, "](chapters/$1)");
    writeFileSync(join(out, f), linkPaths(up, "."));
  } else {
    // `{{#include ../src/...}}` is written relative to chapters/ in the repository;
    // staged, the chapter sits two folders deeper (target/book-src/chapters/).
    const down = text
      .replace(/\]\(preface\.md/g, "](../preface.md")
      .replace(/\{\{#include \.\.\//g, "{{#include ../../../");
    writeFileSync(join(out, "chapters", f), linkPaths(down, "chapters"));
  }
}

// Write the pages; a folder page adds its files, which are written in the next rounds.
const written = new Set();
for (let round = 0; round < 10; round += 1) {
  const todo = [...pages].filter(([p]) => !written.has(p));
  if (todo.length === 0) break;
  for (const [path, page] of todo) {
    written.add(path);
    mkdirSync(dirname(join(out, page)), { recursive: true });
    const clean = path.replace(/\/$/, "");
    writeFileSync(join(out, page), path.endsWith("/") ? folderPage(clean) : filePage(clean));
  }
}

// The summary: book/SUMMARY.md, then the source pages, folded under one index page.
const sorted = [...pages].sort(([a], [b]) => a.localeCompare(b));
const index = [
  "# Source files",
  "",
  "The repository files the course names, as they were when this book was built. Each",
  "chapter links here wherever it names a file; the code that runs is the code shown.",
  "",
  ...sorted.map(([path, page]) => `- [\`${path}\`](${posix.relative("code", page)})`),
  "",
];
writeFileSync(join(out, "code", "index.md"), index.join("\n"));
let summary = readFileSync(join(root, "book", "SUMMARY.md"), "utf8").replace(/\n*$/, "\n");
summary += "- [Source files](code/index.md)\n";
for (const [path, page] of sorted) summary += `    - [${path}](${page})\n`;
writeFileSync(join(out, "SUMMARY.md"), summary);
console.error(`stage: ${pages.size} repository files and folders linked from the course`);
