/* flake8-rosgraph graph page: draws the views laid out by graph/html.py, and filters, searches,
 * pans, zooms and explains on click. Plain DOM and SVG, no libraries, nothing fetched. */
(function () {
  "use strict";
  var SVG_NS = "http://www.w3.org/2000/svg";
  var data = JSON.parse(document.getElementById("rosgraph-data").textContent);
  var state = { view: 0, search: "", pkg: "", ns: "", launch: "", code: "", infra: false, selected: -1 };
  var ui = {};
  var box = { x: 0, y: 0, w: 100, h: 100 };
  /* Below this many screen pixels per drawing unit, labels are too small to read. */
  var MIN_SCALE = 0.7;

  function el(tag, attrs, parent, text) {
    var node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { node.setAttribute(k, attrs[k]); });
    if (text !== undefined) { node.textContent = text; }
    if (parent) { parent.appendChild(node); }
    return node;
  }

  function svg(tag, attrs, parent) {
    var node = document.createElementNS(SVG_NS, tag);
    Object.keys(attrs || {}).forEach(function (k) { node.setAttribute(k, attrs[k]); });
    if (parent) { parent.appendChild(node); }
    return node;
  }

  function view() { return data.views[state.view]; }

  function unique(values) {
    var seen = {};
    values.forEach(function (v) { if (v !== null && v !== undefined && v !== "") { seen[v] = true; } });
    return Object.keys(seen).sort();
  }

  function fillSelect(select, label, values) {
    select.textContent = "";
    el("option", { value: "" }, select, label);
    values.forEach(function (v) { el("option", { value: v }, select, v); });
    select.disabled = values.length === 0;
  }

  function buildToolbar() {
    var app = el("div", { id: "app" }, document.body);
    var header = el("header", {}, app);
    el("h1", {}, header, data.title);
    ui.view = el("select", { id: "view", title: "what to show" }, header);
    data.views.forEach(function (v, i) { el("option", { value: String(i) }, ui.view, v.title); });
    ui.view.disabled = data.views.length < 2;
    ui.search = el("input", { id: "search", type: "search", placeholder: "search names, types, files" }, header);
    ui.pkg = el("select", { id: "filter-package", title: "package" }, header);
    ui.ns = el("select", { id: "filter-namespace", title: "namespace" }, header);
    ui.launch = el("select", { id: "filter-launch", title: "launch file" }, header);
    ui.code = el("select", { id: "filter-finding", title: "finding" }, header);
    var infra = el("label", {}, header);
    ui.infra = el("input", { id: "show-infra", type: "checkbox" }, infra);
    infra.appendChild(document.createTextNode("infrastructure"));
    ui.fit = el("button", { id: "fit", type: "button" }, header, "fit");
    ui.counts = el("span", { id: "counts" }, header);
    var main = el("main", {}, app);
    ui.canvas = svg("svg", { id: "canvas" }, main);
    var defs = svg("defs", {}, ui.canvas);
    [["arrow", "#6b7280"], ["arrow-red", "#d7263d"]].forEach(function (m) {
      var marker = svg("marker", { id: m[0], viewBox: "0 0 10 10", refX: "10", refY: "5",
                                   markerWidth: "7", markerHeight: "7", orient: "auto" }, defs);
      svg("path", { d: "M0,0 L10,5 L0,10 z", fill: m[1] }, marker);
    });
    ui.edges = svg("g", { id: "edges" }, ui.canvas);
    ui.vertices = svg("g", { id: "vertices" }, ui.canvas);
    ui.panel = el("aside", { id: "panel" }, main);
  }

  function refreshFilters() {
    var v = view();
    var nodes = v.vertices.filter(function (x) { return x.kind === "node"; });
    fillSelect(ui.pkg, "all packages", unique(nodes.map(function (x) { return x.package; })));
    fillSelect(ui.ns, "all namespaces", unique(nodes.map(function (x) { return x.namespace; })));
    var launches = [];
    nodes.forEach(function (x) { launches = launches.concat(x.launch); });
    fillSelect(ui.launch, "all launch files", unique(launches));
    var codes = [];
    v.vertices.forEach(function (x) { x.findings.forEach(function (f) { codes.push(f.code); }); });
    fillSelect(ui.code, "all findings", unique(codes));
  }

  function shapeOf(vx, g) {
    var x = vx.x - vx.w / 2, y = vx.y - vx.h / 2;
    if (vx.kind === "node") {
      return svg("rect", { class: "shape", x: x, y: y, width: vx.w, height: vx.h, rx: Math.min(vx.h / 2, 18) }, g);
    }
    if (vx.kind === "action") {
      var d = Math.min(10, vx.h / 2);
      var points = [[x + d, y], [x + vx.w - d, y], [x + vx.w, vx.y], [x + vx.w - d, y + vx.h],
                    [x + d, y + vx.h], [x, vx.y]].map(function (p) { return p.join(","); }).join(" ");
      return svg("polygon", { class: "shape", points: points }, g);
    }
    var rect = svg("rect", { class: "shape", x: x, y: y, width: vx.w, height: vx.h }, g);
    if (vx.kind === "service") {
      svg("line", { class: "shape", x1: x + 6, y1: y, x2: x + 6, y2: y + vx.h }, g);
      svg("line", { class: "shape", x1: x + vx.w - 6, y1: y, x2: x + vx.w - 6, y2: y + vx.h }, g);
    }
    return rect;
  }

  function edgePath(a, b, via) {
    var forward = b.x > a.x;
    var points = [[forward ? a.x + a.w / 2 : a.x - a.w / 2, a.y]].concat(via)
      .concat([[forward ? b.x - b.w / 2 : b.x + b.w / 2, b.y]]);
    if (a.x === b.x) {
      var out = a.x + a.w / 2, back = b.x + b.w / 2, far = Math.max(out, back) + 60;
      return "M" + out + "," + a.y + " C" + far + "," + a.y + " " + far + "," + b.y + " " + back + "," + b.y;
    }
    var d = "M" + points[0][0] + "," + points[0][1];
    for (var i = 1; i < points.length; i += 1) {
      var p = points[i - 1], q = points[i], mid = (p[0] + q[0]) / 2;
      d += " C" + mid + "," + p[1] + " " + mid + "," + q[1] + " " + q[0] + "," + q[1];
    }
    return d;
  }

  function draw() {
    var v = view();
    ui.edges.textContent = "";
    ui.vertices.textContent = "";
    v.edges.forEach(function (e, i) {
      var a = v.vertices[e.s], b = v.vertices[e.t];
      var cls = "edge" + (e.dashed ? " dashed" : "") + (e.loop ? " loop" : "") +
                (a.exempt || b.exempt ? " exempt" : "") + (e.findings.length ? " has-finding" : "");
      var p = svg("path", { class: cls, d: edgePath(a, b, e.via), "data-edge": String(i),
                            "marker-end": e.findings.length || e.loop ? "url(#arrow-red)" : "url(#arrow)" }, ui.edges);
      var title = svg("title", {}, p);
      title.textContent = a.label[0] + " \u2192 " + b.label[0] + " (" + e.role + ")" +
        e.findings.map(function (f) { return "\n" + f.code + " " + f.message; }).join("");
    });
    v.links.forEach(function (link, i) {
      var a = v.vertices[link.s], b = v.vertices[link.t];
      var p = svg("path", { class: "near-miss", "data-link": String(i),
                            d: "M" + a.x + "," + a.y + " L" + b.x + "," + b.y }, ui.edges);
      svg("title", {}, p).textContent = link.message;
    });
    v.vertices.forEach(function (vx, i) {
      var cls = "vertex kind-" + vx.kind + (vx.unknown ? " unknown" : "") + (vx.exempt ? " exempt" : "") +
                (vx.orphan ? " orphan" : "") + (vx.findings.length ? " has-finding" : "");
      var g = svg("g", { class: cls, "data-index": String(i), "data-id": vx.id }, ui.vertices);
      shapeOf(vx, g);
      var top = vx.y - (vx.label.length - 1) * 8;
      vx.label.forEach(function (line, k) {
        var t = svg("text", { x: vx.x, y: top + k * 16 + 4, "text-anchor": "middle" }, g);
        t.textContent = line;
      });
      g.addEventListener("click", function (ev) { ev.stopPropagation(); select(i); });
    });
  }

  function nodeMatchesFilters(vx) {
    return (!state.pkg || vx.package === state.pkg) && (!state.ns || vx.namespace === state.ns) &&
           (!state.launch || vx.launch.indexOf(state.launch) >= 0);
  }

  function hasCode(list) {
    return list.some(function (f) { return f.code === state.code; });
  }

  function visibility() {
    var v = view();
    var filtered = state.pkg || state.ns || state.launch || state.code;
    var nodeShown = v.vertices.map(function (vx, i) {
      if (!filtered) { return true; }
      if (vx.kind !== "node" || !nodeMatchesFilters(vx)) { return false; }
      return !state.code || hasCode(vx.findings) || v.edges.some(function (e) {
        return (e.s === i || e.t === i) && hasCode(e.findings);
      });
    });
    var shown = nodeShown.slice();
    if (filtered) {
      v.edges.forEach(function (e) {
        if (v.vertices[e.s].kind === "node" && nodeShown[e.s]) { shown[e.t] = true; }
        if (v.vertices[e.t].kind === "node" && nodeShown[e.t]) { shown[e.s] = true; }
      });
    }
    return v.vertices.map(function (vx, i) { return shown[i] && (state.infra || !vx.exempt); });
  }

  function searchText(vx) {
    var parts = vx.label.concat([vx.id, vx.where || "", vx.package || ""]);
    vx.entities.forEach(function (row) { parts = parts.concat(row); });
    return parts.join("\n").toLowerCase();
  }

  function apply() {
    var v = view();
    var shown = visibility();
    var query = state.search.trim().toLowerCase();
    var matches = 0, nodes = 0;
    Array.prototype.forEach.call(ui.vertices.children, function (g) {
      var i = Number(g.getAttribute("data-index"));
      var vx = v.vertices[i];
      var hit = query !== "" && searchText(vx).indexOf(query) >= 0;
      g.classList.toggle("hidden", !shown[i]);
      g.classList.toggle("match", hit && shown[i]);
      g.classList.toggle("dim", query !== "" && !hit);
      g.classList.toggle("selected", i === state.selected);
      if (hit && shown[i]) { matches += 1; }
      if (shown[i] && vx.kind === "node") { nodes += 1; }
    });
    Array.prototype.forEach.call(ui.edges.children, function (p) {
      var idx = p.getAttribute("data-edge");
      var e = idx === null ? v.links[Number(p.getAttribute("data-link"))] : v.edges[Number(idx)];
      p.classList.toggle("hidden", !(shown[e.s] && shown[e.t]));
      p.classList.toggle("dim", query !== "");
    });
    ui.counts.textContent = nodes + " nodes shown" + (query ? ", " + matches + " matching" : "");
  }

  function cell(row, text, cls) {
    el("td", cls ? { class: cls } : {}, row, text);
  }

  function findingList(parent, findings) {
    findings.forEach(function (f) {
      var div = el("div", { class: "finding" }, parent);
      el("b", {}, div, f.code + " ");
      div.appendChild(document.createTextNode(f.message + " "));
      el("span", { class: "where" }, div, f.where);
    });
  }

  function neighbours(i) {
    var v = view(), rows = [];
    v.edges.forEach(function (e) {
      if (e.s === i) { rows.push([e.role, v.vertices[e.t].label[0]]); }
      if (e.t === i) { rows.push([e.role + " (by)", v.vertices[e.s].label[0]]); }
    });
    return rows;
  }

  function showPanel() {
    var v = view();
    ui.panel.textContent = "";
    if (state.selected < 0) {
      el("h2", {}, ui.panel, v.title);
      el("p", { class: "hint" }, ui.panel, "Click a node, topic, service or action for its details. " +
         "Drag to pan, wheel to zoom.");
      var all = [];
      v.vertices.forEach(function (vx) { all = all.concat(vx.findings); });
      var seen = {};
      all = all.filter(function (f) { var k = f.code + f.where + f.message; if (seen[k]) { return false; } seen[k] = true; return true; });
      el("h3", {}, ui.panel, "findings (" + all.length + ")");
      findingList(ui.panel, all);
      var legend = el("div", { class: "legend" }, ui.panel);
      [["node", "#7fffd4"], ["topic", "#fff68f"], ["orphan topic", "#ffa94d"], ["service", "#add8e6"],
       ["action", "#dda0dd"], ["unknown name", "#ffffff"], ["infrastructure", "#eceff3"]].forEach(function (item) {
        el("span", { style: "--swatch: " + item[1] }, legend, item[0]);
      });
      return;
    }
    var vx = v.vertices[state.selected];
    el("h2", { id: "panel-title" }, ui.panel, vx.label[0]);
    var facts = el("table", {}, ui.panel);
    [["kind", vx.kind], ["package", vx.package], ["namespace", vx.namespace], ["created at", vx.where],
     ["launched by", vx.launch.join(", ")]].forEach(function (f) {
      if (f[1]) { var r = el("tr", {}, facts); cell(r, f[0]); cell(r, f[1], f[0] === "created at" ? "where" : ""); }
    });
    if (vx.findings.length) {
      el("h3", {}, ui.panel, "findings");
      findingList(ui.panel, vx.findings);
    }
    if (vx.entities.length) {
      el("h3", {}, ui.panel, "entities");
      var table = el("table", { id: "entities" }, ui.panel);
      vx.entities.forEach(function (row) {
        var r = el("tr", {}, table);
        cell(r, row[0]); cell(r, row[1]); cell(r, row[2]); cell(r, row[3], "where");
      });
    }
    var rows = neighbours(state.selected);
    if (rows.length) {
      el("h3", {}, ui.panel, "connections");
      var conn = el("table", {}, ui.panel);
      rows.forEach(function (row) { var r = el("tr", {}, conn); cell(r, row[0]); cell(r, row[1]); });
    }
  }

  function select(i) {
    state.selected = i;
    apply();
    showPanel();
  }

  function setBox(b) {
    box = b;
    ui.canvas.setAttribute("viewBox", [b.x, b.y, b.w, b.h].join(" "));
  }

  function bounds() {
    var v = view(), shown = visibility();
    var x1 = Infinity, y1 = Infinity, x2 = -Infinity, y2 = -Infinity;
    v.vertices.forEach(function (vx, i) {
      if (!shown[i]) { return; }
      x1 = Math.min(x1, vx.x - vx.w / 2); y1 = Math.min(y1, vx.y - vx.h / 2);
      x2 = Math.max(x2, vx.x + vx.w / 2); y2 = Math.max(y2, vx.y + vx.h / 2 + 40);
    });
    if (x1 === Infinity) { x1 = 0; y1 = 0; x2 = 100; y2 = 100; }
    return { x: x1 - 20, y: y1 - 20, w: x2 - x1 + 40, h: y2 - y1 + 40 };
  }

  function fit() {
    setBox(bounds());
  }

  /* The first look: everything when it fits at a readable size, else the sources (left) at that size. */
  function firstLook() {
    var all = bounds(), r = ui.canvas.getBoundingClientRect();
    var scale = Math.min(r.width / all.w, r.height / all.h);
    if (!(scale < MIN_SCALE)) {
      setBox(all);
      return;
    }
    var w = r.width / MIN_SCALE, h = r.height / MIN_SCALE;
    setBox({ x: all.x, y: all.y + all.h / 2 - h / 2, w: w, h: h });
  }

  function enablePanZoom() {
    var drag = null;
    ui.canvas.addEventListener("wheel", function (ev) {
      ev.preventDefault();
      var r = ui.canvas.getBoundingClientRect();
      var scale = ev.deltaY > 0 ? 1.15 : 1 / 1.15;
      var px = box.x + (ev.clientX - r.left) / r.width * box.w;
      var py = box.y + (ev.clientY - r.top) / r.height * box.h;
      setBox({ x: px - (px - box.x) * scale, y: py - (py - box.y) * scale, w: box.w * scale, h: box.h * scale });
    }, { passive: false });
    ui.canvas.addEventListener("pointerdown", function (ev) {
      drag = { x: ev.clientX, y: ev.clientY, box: box };
      ui.canvas.classList.add("panning");
    });
    window.addEventListener("pointermove", function (ev) {
      if (!drag) { return; }
      var r = ui.canvas.getBoundingClientRect();
      var k = Math.max(drag.box.w / r.width, drag.box.h / r.height);
      setBox({ x: drag.box.x - (ev.clientX - drag.x) * k, y: drag.box.y - (ev.clientY - drag.y) * k,
               w: drag.box.w, h: drag.box.h });
    });
    window.addEventListener("pointerup", function () { drag = null; ui.canvas.classList.remove("panning"); });
    ui.canvas.addEventListener("click", function (ev) { if (ev.target === ui.canvas) { select(-1); } });
  }

  function showView(i) {
    state.view = i;
    state.selected = -1;
    state.pkg = state.ns = state.launch = state.code = "";
    refreshFilters();
    draw();
    apply();
    showPanel();
    firstLook();
  }

  function onFilter(select, key) {
    select.addEventListener("change", function () { state[key] = select.value; state.selected = -1; apply(); showPanel(); fit(); });
  }

  buildToolbar();
  ui.view.addEventListener("change", function () { showView(Number(ui.view.value)); });
  ui.search.addEventListener("input", function () { state.search = ui.search.value; apply(); });
  onFilter(ui.pkg, "pkg");
  onFilter(ui.ns, "ns");
  onFilter(ui.launch, "launch");
  onFilter(ui.code, "code");
  ui.infra.addEventListener("change", function () { state.infra = ui.infra.checked; apply(); fit(); });
  ui.fit.addEventListener("click", fit);
  enablePanZoom();
  showView(0);
  document.body.setAttribute("data-ready", "1");
}());
