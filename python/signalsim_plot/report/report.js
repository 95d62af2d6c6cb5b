// The table of runs of report.html: built from the inline JSON (#report-data), sorted by a click on a
// column's header, filtered by status, by text and by a heat-map cell (#cell=<JSON of column: value>).
// The first FIRST_ROWS matching rows are drawn, the others on "show all": the browser's layout of a
// table of thousands of rows, not the script, is what takes seconds.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const cols = data.columns, rows = data.rows, pageAt = cols.length;
  const index = Object.fromEntries(cols.map((c, i) => [c.key, i]));
  const tbody = document.querySelector("#runs tbody");
  const headRow = document.querySelector("#runs thead tr");
  const statusFilter = document.getElementById("status-filter");
  const textFilter = document.getElementById("text-filter");
  const shown = document.getElementById("shown");
  const cellNote = document.getElementById("cell-filter");
  const FIRST_ROWS = 200;
  let sortAt = 0, direction = 1, cell = null, limit = FIRST_ROWS;

  const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", "\"": "&quot;"})[c]);
  headRow.innerHTML = cols.map((c, i) => `<th data-at="${i}" title="${esc(c.title || "")}">${esc(c.label)}</th>`).join("");

  function cellHtml(c, value, row) {
    if (value === null || value === undefined) return c.kind === "num" ? "<td class=\"num\"></td>" : "<td></td>";
    if (c.kind === "num") return `<td class="num">${esc(value)}</td>`;
    if (c.kind === "status") return `<td><span class="st st-${esc(value)}">${esc(value)}</span></td>`;
    if (c.kind === "link") return `<td><a href="${esc(row[pageAt])}">${esc(value)}</a></td>`;
    return `<td class="${c.kind === "problem" ? "problem" : ""}">${esc(value)}</td>`;
  }

  function compare(a, b) {
    const x = a[sortAt], y = b[sortAt];
    if (x === y) return a[0] - b[0];
    if (x === null || x === undefined || x === "") return 1;   // empty cells last either way
    if (y === null || y === undefined || y === "") return -1;
    return (typeof x === "number" && typeof y === "number" ? x - y : String(x).localeCompare(String(y))) * direction;
  }

  function render() {
    const status = statusFilter.value, text = textFilter.value.trim().toLowerCase();
    const list = rows.filter((r) =>
      (!status || r[index.status] === status) &&
      (!cell || Object.entries(cell).every(([k, v]) => k in index && String(r[index[k]]) === v)) &&
      (!text || r.slice(0, pageAt).some((v) => v !== null && String(v).toLowerCase().includes(text))));
    list.sort(compare);
    const drawn = list.slice(0, limit);
    tbody.innerHTML = drawn.map((r) => "<tr>" + cols.map((c, i) => cellHtml(c, r[i], r)).join("") + "</tr>").join("");
    shown.innerHTML = drawn.length < list.length
      ? `${drawn.length} of the ${list.length} matching runs shown (of ${rows.length}) <button id="show-all">show all</button>`
      : `${list.length} of ${rows.length} runs shown`;
    headRow.querySelectorAll("th").forEach((th, i) => th.className = i === sortAt ? (direction > 0 ? "asc" : "desc") : "");
  }

  function readHash() {
    cell = null;
    const m = location.hash.match(/^#cell=(.*)$/);
    if (m) {
      try { cell = JSON.parse(decodeURIComponent(m[1])); } catch (e) { cell = null; }
    }
    cellNote.innerHTML = cell ? "cell: " + esc(Object.entries(cell).map(([k, v]) => `${k}=${v}`).join(", ")) +
      " <a href=\"#\" id=\"clear-cell\">show all</a>" : "";
    render();
  }

  headRow.addEventListener("click", (e) => {
    const th = e.target.closest("th");
    if (!th) return;
    const at = Number(th.dataset.at);
    direction = at === sortAt ? -direction : 1;
    sortAt = at;
    render();
  });
  shown.addEventListener("click", (e) => {
    if (e.target.id !== "show-all") return;
    limit = Infinity;
    render();
  });
  statusFilter.addEventListener("change", render);
  textFilter.addEventListener("input", render);
  window.addEventListener("hashchange", readHash);
  readHash();
  document.body.dataset.rendered = "yes";  // the table is built (read by tests)
  document.body.dataset.renderedMs = String(Math.round(performance.now()));  // since navigation (bench)
})();
