// Wide tables on a phone: each cell gets its column's header as a label (data-label), and
// the stylesheet (book/book.css, max-width 620px) shows a table of four or more columns
// as one card per row, "header: value" per line, instead of columns a few letters wide.
// Without JavaScript the tables still fit the screen, only without the labels.
(() => {
  for (const table of document.querySelectorAll(".content main table")) {
    const heads = [...table.querySelectorAll("thead th")].map((th) => th.textContent.trim());
    if (heads.length < 4) continue;
    table.classList.add("cards");
    for (const tr of table.querySelectorAll("tbody tr")) {
      [...tr.children].forEach((td, i) => td.setAttribute("data-label", heads[i] ?? ""));
    }
  }
})();
