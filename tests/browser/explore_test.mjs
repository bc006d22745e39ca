// epure explore in a real browser: Debian's headless chromium, driven by puppeteer-core.
//   node explore_test.mjs PAGE LINES EXPECTED SET_DIR OUT_DIR LONG LONG_EXPECTED
// PAGE: explore.html written by `epure explore`; LINES / EXPECTED: solve input lines and what
// `epure solve` printed for them; SET_DIR: a set written by `epure generate` (its explore.html,
// key.json); OUT_DIR: screenshots and timings.json; LONG / LONG_EXPECTED: lines with digits beyond
// a double's and what `epure solve` printed for them. Every request outside the page's own file is
// refused (and counted as a failure). Prints one line per check, then "N passed, M failed".
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import puppeteer from "puppeteer-core";

const [pagePath, linesPath, expectedPath, setDir, outDir, longPath, longExpectedPath] = process.argv.slice(2);
fs.mkdirSync(outDir, { recursive: true });
let passed = 0, failed = 0;
function check(ok, what, detail = "") {
  if (ok) passed++;
  else failed++;
  console.log(`${ok ? "ok  " : "FAIL"} ${what}${detail ? ": " + detail : ""}`);
}

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--allow-file-access-from-files=false"],
});

// A page on `file`, with every other request refused and every console error recorded.
async function open(file, hash = "") {
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1000, hasTouch: true });
  const url = pathToFileURL(path.resolve(file)).href;
  const refused = [], errors = [];
  await page.setRequestInterception(true);
  page.on("request", req => {
    const u = req.url();
    if (u === url || u === url + hash || u.startsWith("data:")) req.continue();
    else { refused.push(u); req.abort(); }
  });
  page.on("console", msg => { if (msg.type() === "error") errors.push(msg.text()); });
  page.on("pageerror", err => errors.push(String(err)));
  await page.goto(url + hash, { waitUntil: "load" });
  await page.waitForFunction(() => window.epure && window.epure.ready, { timeout: 30000 });
  return { page, refused, errors };
}

// A mouse drag of the element `selector` from its centre, `moves` steps of (dx, dy) pixels;
// `during`, when given, runs before the button is released, and its result is returned.
async function mouseDrag(page, selector, moves, dx, dy, during) {
  const box = await (await page.$(selector)).boundingBox();
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= moves; k++) await page.mouse.move(x + dx * k, y + dy * k);
  const seen = during ? await during() : undefined;
  await page.mouse.up();
  return seen;
}

function quantile(xs, q) {
  const s = [...xs].sort((a, b) => a - b);
  if (!s.length) return NaN;
  return s[Math.min(s.length - 1, Math.floor(q * s.length))];
}

// ---- 1. epure.solve is `epure solve`, bit for bit ----------------------------------------------
const lines = fs.readFileSync(linesPath, "utf8").split("\n").filter(l => l.trim() !== "");
const expected = fs.readFileSync(expectedPath, "utf8").split("\n").filter(l => l !== "");
check(lines.length === expected.length, "solve: one native result per line", `${lines.length} / ${expected.length}`);
{
  const { page, refused, errors } = await open(pagePath);
  const r = await page.evaluate((lines, expected) => {
    // equal as values, every number by its bits (Object.is tells -0 from 0)
    const same = (a, b) => {
      if (typeof a === "number" || typeof b === "number") return Object.is(a, b);
      if (Array.isArray(a)) return Array.isArray(b) && a.length === b.length && a.every((x, i) => same(x, b[i]));
      if (a && typeof a === "object") {
        const ka = Object.keys(a), kb = Object.keys(b || {});
        return ka.length === kb.length && ka.every((k, i) => k === kb[i] && same(a[k], b[k]));
      }
      return a === b;
    };
    const lossless = v => {  // an object whose doubles JSON.stringify keeps (no -0, no infinity)
      if (typeof v === "number") return Number.isFinite(v) && !Object.is(v, -0);
      if (Array.isArray(v)) return v.every(lossless);
      if (v && typeof v === "object") return Object.values(v).every(lossless);
      return true;
    };
    let text = 0, objects = 0, objectsTried = 0;
    const bad = [], kinds = {};
    lines.forEach((line, i) => {
      const want = JSON.parse(expected[i]);
      const got = window.epure.solve(line);
      if (same(got, want)) text++;
      else if (bad.length < 5) bad.push({ line, got: JSON.stringify(got), want: expected[i] });
      let obj = null;
      try { obj = JSON.parse(line); } catch (e) { obj = null; }
      if (obj && typeof obj === "object" && !Array.isArray(obj) && lossless(obj)) {
        objectsTried++;
        // an object's numbers are doubles: they mean the decimals JSON.stringify writes for them
        // (README, "What a number means"), which need not be the line's own (0.30000000000000001)
        const asText = window.epure.solve(JSON.stringify(obj));
        if (same(window.epure.solve(obj), asText)) objects++;
        else if (bad.length < 5) bad.push({ object: line, got: JSON.stringify(window.epure.solve(obj)), want: JSON.stringify(asText) });
        if (typeof obj.kind === "string") kinds[obj.kind] = (kinds[obj.kind] || 0) + 1;
      }
    });
    return { text, objects, objectsTried, bad, kinds };
  }, lines, expected);
  check(r.text === lines.length, `solve: ${r.text}/${lines.length} lines (as text) equal to epure solve`, JSON.stringify(r.bad));
  check(r.objects === r.objectsTried, `solve: ${r.objects}/${r.objectsTried} lines (as objects) equal to epure solve`);
  console.log(`     lines per kind: ${JSON.stringify(r.kinds)}`);
  check(refused.length === 0 && errors.length === 0, "solve page: no request outside the file, no console error",
        JSON.stringify({ refused, errors }));
  await page.close();
}

// ---- 2. every view: figure, handles, mouse drag, keyboard, touch, timings -------------------------
const timings = {};
const spaceKinds = ["vectors_3d", "ray_sphere", "ray_cube"];
{
  const { page, refused, errors } = await open(pagePath);
  const kinds = await page.evaluate(() => window.epure.kinds());
  check(kinds.length >= 10 && spaceKinds.every(k => kinds.includes(k)), "views: one per kind, in the plane and in space", kinds.join(" "));
  const shown = () => ({
    current: window.epure.current(),
    svg: document.querySelector("#figure svg").outerHTML,
    steps: document.getElementById("steps").textContent,
    handles: [...document.querySelectorAll("#figure [data-handle]")].map(h => h.dataset.handle),
  });
  const handleAt = (svg, id) => (svg.match(new RegExp(`data-handle="${id.replace(".", "\\.")}" cx="([^"]+)" cy="([^"]+)"`)) || []).slice(1);
  for (const kind of kinds) {
    await page.click(`#views button[data-kind="${kind}"]`);
    await page.waitForFunction(k => document.querySelector(`#views button[aria-pressed="true"]`)?.dataset.kind === k, {}, kind);
    const before = await page.evaluate(shown);
    await page.screenshot({ path: path.join(outDir, `view-${kind}.png`) });
    check(before.steps.length > 100 && !(await page.$eval("#error", e => e.textContent)), `${kind}: worked steps shown`);
    const space = spaceKinds.includes(kind);
    check(before.handles.length >= 2, `${kind}: handles`, before.handles.join(" "));
    if (space) {
      const hint = await page.$eval("#hint", e => e.textContent);
      const toggle = await page.$eval("#height-toggle", e => !e.hidden);
      check(toggle && /Shift/.test(hint), `${kind}: the 3D view says how to drag in height`, hint.slice(0, 60));
    }

    // every handle dragged with the mouse, 12 moves each, each checked: the datum, the figure, the
    // numbers and the handle move (in a 3D view, in the horizontal plane: z kept)
    const start = await page.evaluate(() => window.epure.timings.length);
    for (const id of before.handles) {
      const was = await page.evaluate(shown);
      const during = await mouseDrag(page, `#figure [data-handle="${id}"]`, 12, 3, -2, () => page.evaluate(shown));
      const field = id.split(".")[0];
      const a = was.current[field], b = during.current[field];
      check(JSON.stringify(b) !== JSON.stringify(a), `${kind}: dragging ${id} moves the datum`, `${JSON.stringify(a)} -> ${JSON.stringify(b)}`);
      if (space && Array.isArray(a))
        check(a[2] === b[2], `${kind}: ${id} dragged in its horizontal plane (z kept)`, `${JSON.stringify(a)} -> ${JSON.stringify(b)}`);
      check(during.svg !== was.svg, `${kind}: dragging ${id} redraws the figure`);
      check(during.steps !== was.steps, `${kind}: dragging ${id} updates the numbers`);
      check(JSON.stringify(handleAt(during.svg, id)) !== JSON.stringify(handleAt(was.svg, id)), `${kind}: the handle ${id} follows`);
    }
    const t = await page.evaluate(s => window.epure.timings.slice(s), start);
    if (space) {
      // Shift: up and down the vertical (x and y kept, z changes); the points' handles only
      for (const id of before.handles.filter(h => Array.isArray(before.current[h]))) {
        const was = await page.evaluate(shown);
        await page.keyboard.down("Shift");
        const during = await mouseDrag(page, `#figure [data-handle="${id}"]`, 8, 2, -4, () => page.evaluate(shown));
        await page.keyboard.up("Shift");
        const a = was.current[id], b = during.current[id];
        check(a[0] === b[0] && a[1] === b[1] && b[2] > a[2], `${kind}: ${id} dragged with Shift goes up its vertical`, `${JSON.stringify(a)} -> ${JSON.stringify(b)}`);
        check(during.svg !== was.svg && during.steps !== was.steps, `${kind}: ${id} dragged with Shift redraws the figure and the numbers`);
      }
    }
    timings[kind] = { moves: t.length, total_median_ms: quantile(t.map(x => x.total), 0.5), total_p95_ms: quantile(t.map(x => x.total), 0.95),
                      handler_median_ms: quantile(t.map(x => x.handler), 0.5), handler_p95_ms: quantile(t.map(x => x.handler), 0.95),
                      core_median_ms: quantile(t.map(x => x.core), 0.5), core_p95_ms: quantile(t.map(x => x.core), 0.95) };

    // keyboard: Tab selects the first handle, an arrow moves it by a tenth
    const k0 = await page.evaluate(() => window.epure.current());
    await page.focus("#figure");
    await page.keyboard.press("Escape");  // the last dragged handle is selected: none now
    await page.keyboard.press("Tab");
    const selected = await page.$eval("#figure .handle.selected", h => h.dataset.handle).catch(() => null);
    check(selected === before.handles[0], `${kind}: Tab selects a handle`, String(selected));
    await page.keyboard.press("Tab");
    const second = await page.$eval("#figure .handle.selected", h => h.dataset.handle).catch(() => null);
    check(second === before.handles[1], `${kind}: Tab cycles to the next handle`, String(second));
    await page.keyboard.press("ArrowUp");
    const k1 = await page.evaluate(() => window.epure.current());
    check(JSON.stringify(k1) !== JSON.stringify(k0), `${kind}: an arrow key moves the selected handle`);
    if (space) {
      // PageUp: along z only, by a tenth
      const f = before.handles[1];
      await page.keyboard.press("PageUp");
      const k2 = await page.evaluate(() => window.epure.current());
      const a = k1[f], b = k2[f];
      check(Array.isArray(a) && a[0] === b[0] && a[1] === b[1] && Math.abs(b[2] - a[2] - 0.1) < 1e-9,
            `${kind}: PageUp moves ${f} up by a tenth`, `${JSON.stringify(a)} -> ${JSON.stringify(b)}`);
    }
  }

  // touch on one view, snap on another
  await page.click(`#views button[data-kind="projection"]`);
  {
    const box = await (await page.$(`#figure [data-handle="C"]`)).boundingBox();
    const c0 = await page.evaluate(() => window.epure.current().C);
    const x = box.x + box.width / 2, y = box.y + box.height / 2;
    await page.touchscreen.touchStart(x, y);
    for (let k = 1; k <= 8; k++) await page.touchscreen.touchMove(x - 4 * k, y + 3 * k);
    await page.touchscreen.touchEnd();
    const c1 = await page.evaluate(() => window.epure.current().C);
    check(JSON.stringify(c0) !== JSON.stringify(c1), "projection: a touch drag moves C", `${c0} -> ${c1}`);
  }
  await page.click("#snap");
  {
    await mouseDrag(page, `#figure [data-handle="A"]`, 10, 7, 5);
    const a = await page.evaluate(() => window.epure.current().A);
    check(a.every(Number.isInteger), "snap: a dragged point lands on the integer grid", JSON.stringify(a));
  }
  // the branch follows the data: C dragged past B puts P after B
  {
    const fr = await page.evaluate(() => { window.epure.show({ kind: "projection", A: [0, 0], B: [4, 0], C: [6, 3] }); return document.getElementById("steps").textContent; });
    const inside = await page.evaluate(() => { window.epure.show({ kind: "projection", A: [0, 0], B: [4, 0], C: [2, 3] }); return document.getElementById("steps").textContent; });
    check(fr !== inside, "projection: the steps change with the branch (after B, between)");
  }
  // French
  await page.select("#lang", "fr");
  const french = await page.$eval("#steps", e => e.textContent);
  check(/Exercice|Solution|donc|produit/i.test(french), "language: the steps in French", french.slice(0, 80));
  await page.screenshot({ path: path.join(outDir, "view-projection-fr.png") });
  // a degenerate figure is said, not drawn
  const err = await page.evaluate(() => window.epure.show({ kind: "projection", A: [1, 1], B: [1, 1], C: [2, 3] }));
  check(typeof err === "string" && err.length > 0, "a degenerate figure gives a clear error", String(err));
  check(refused.length === 0, "views: no request outside the file", JSON.stringify(refused));
  check(errors.length === 0, "views: no console error", JSON.stringify(errors));
  await page.close();
}

// ---- 1b. digits beyond a double's: shown as written, never another verdict than solve's --------
{
  const long = fs.readFileSync(longPath, "utf8").split("\n").filter(l => l.trim());
  const want = fs.readFileSync(longExpectedPath, "utf8").split("\n").filter(l => l.trim());
  check(long.length > 0 && long.length === want.length, "long digits: one native result per line", `${long.length} / ${want.length}`);
  const { page, refused, errors } = await open(pagePath);
  const r = await page.evaluate((long, want) => {
    const out = [];
    long.forEach((line, i) => {
      // the digits written, each number of 18 significant digits or more
      const digits = line.match(/-?\d+\.\d{17,}(e-?\d+)?/g) || [];
      const error = window.epure.show(line);
      const solved = JSON.stringify(window.epure.solve(line)) === JSON.stringify(JSON.parse(want[i]));
      delete window.epureCopied;
      document.getElementById("copy").click();
      const copied = window.epureCopied || "";
      const steps = document.getElementById("steps").textContent;
      out.push({ line, error, solved, digits, copied, steps: steps.length,
                 // shown: the view of these data, their digits kept; refused: the error gives solve's answer
                 shown: error === null && digits.every(d => copied.includes(d)) &&
                        JSON.stringify(window.epure.solve(copied)) === JSON.stringify(JSON.parse(want[i])),
                 refused: error !== null && error.includes(want[i]) });
    });
    return out;
  }, long, want);
  for (const x of r) {
    check(x.solved, `long digits: epure.solve is epure solve's, bit for bit: ${x.line}`);
    check(x.shown || x.refused, `long digits: ${x.shown ? "shown with its digits and solve's answer" : "refused with solve's answer"}: ${x.line}`,
          JSON.stringify({ error: x.error, copied: x.copied }));
  }
  check(r.some(x => x.shown) && r.some(x => x.refused), "long digits: some shown, some refused (both paths tried)");
  check(refused.length === 0 && errors.length === 0, "long digits: no request outside the file, no console error", JSON.stringify({ refused, errors }));
  await page.close();
}

// ---- 2b. the page reads like the PDFs: language, title, tab names, arrows, no raw JSON -----------
{
  const raw = fs.readFileSync(pagePath, "utf8");
  const { page, refused, errors } = await open(pagePath);
  const words = lang => page.evaluate(l => JSON.parse(window.Module.words(l)), lang);
  const en = await words("en"), fr = await words("fr");
  check(raw.includes('<html lang="en">') && raw.includes(`<title>${en.title}</title>`),
        "page: lang and title in the markup itself (English page)", (raw.match(/<title>[^<]*<\/title>/) || [""])[0]);
  for (const [lang, w] of [["en", en], ["fr", fr]]) {
    await page.select("#lang", lang);
    const got = await page.evaluate(() => ({
      lang: document.documentElement.lang, title: document.title,
      tabs: [...document.querySelectorAll("#views button")].map(b => [b.dataset.kind, b.textContent]),
    }));
    check(got.lang === lang && got.title === w.title && w.title.length > 0, `page (${lang}): lang and title`, JSON.stringify([got.lang, got.title]));
    const bad = got.tabs.filter(([k, t]) => t !== w["tab." + k] || /_/.test(t) || t === k);
    check(got.tabs.length >= 10 && bad.length === 0, `page (${lang}): tabs named as the course names the exercises`, JSON.stringify(bad.length ? bad : got.tabs.map(t => t[1])));
  }
  // a view of its own is titled by the exercise's name, not "Exercise 1"
  await page.click(`#views button[data-kind="vectors"]`);
  const h = await page.$eval("#steps h2", e => e.textContent);
  check(h.length > 0 && !/^Exerci[cs]e/.test(h), "page: a view outside a sheet is titled by the exercise's name", h);
  // vectors wear an arrow, as on paper: no bar (a mesure algébrique in French), an arrowhead drawn
  const vec = await page.$$eval("#steps .vec", els => els.map(e => {
    const c = getComputedStyle(e);
    return { border: c.borderTopWidth, image: c.backgroundImage, width: e.getBoundingClientRect().width };
  }));
  check(vec.length > 0 && vec.every(v => v.border === "0px" && /svg/.test(v.image) && /gradient/.test(v.image) && v.width > 0),
        "page: vectors drawn with an arrow over their name, not a bar", JSON.stringify(vec.slice(0, 2)));
  await page.screenshot({ path: path.join(outDir, "view-vectors-fr-arrows.png"), clip: { x: 0, y: 0, width: 1400, height: 700 } });
  // no JSON on the page; the data go to the clipboard as a solve line
  const text = await page.evaluate(() => document.body.innerText);
  check(!/\{"kind"/.test(text) && !(await page.$("#data")), "page: no raw JSON on the page", text.slice(-120));
  await page.click("#copy");
  await page.waitForFunction(() => window.epureCopied !== undefined, { timeout: 5000 }).catch(() => {});
  const copied = await page.evaluate(() => ({ line: window.epureCopied, current: window.epure.current(), status: document.getElementById("copied").textContent }));
  check(typeof copied.line === "string" && JSON.stringify(JSON.parse(copied.line)) === JSON.stringify(copied.current) &&
        copied.status === (await words(await page.evaluate(() => document.documentElement.lang))).copied,
        "page: “copy as a solve line” copies the data shown", `${copied.line} (${copied.status})`);
  check(refused.length === 0 && errors.length === 0, "page: no request outside the file, no console error", JSON.stringify({ refused, errors }));
  await page.close();
}

// ---- 3. a student's own exercise from a link ------------------------------------------------------
{
  const key = JSON.parse(fs.readFileSync(path.join(setDir, "key.json"), "utf8"));
  const index = fs.readFileSync(path.join(setDir, "index.html"), "utf8");
  let good = 0, total = 0;
  for (const sheet of key.sheets.slice(0, 2)) {
    for (const ex of sheet.exercises) {
      total++;
      const hash = `#${sheet.id}.${ex.n}`;
      if (!index.includes(`explore.html${hash}"`)) { console.log(`     index.html has no link ${hash}`); continue; }
      const { page, refused, errors } = await open(path.join(setDir, "explore.html"), hash);
      const cur = await page.evaluate(() => window.epure.current());
      const want = typeof ex.instance === "string" ? JSON.parse(ex.instance) : ex.instance;
      const same = JSON.stringify(cur) === JSON.stringify(want);
      // titled as on the sheet: the course's own headings, else "Exercise <its number>"
      const h2 = await page.$eval("#steps h2", e => e.textContent);
      const course = { P: "Preamble", "3.3": "Exercise 3, question 3", "4.3": "Exercise 4, question 3" };
      const title = course[ex.number] || `Exercise ${ex.number}`;
      const titled = typeof ex.number === "string" && h2.startsWith(title + " — ");
      if (same && titled && !refused.length && !errors.length) good++;
      else console.log(`     ${hash}: ${JSON.stringify(cur)} vs ${JSON.stringify(want)}, "${h2}" (number ${ex.number}) ${JSON.stringify({ refused, errors })}`);
      await page.close();
    }
  }
  check(total > 0 && good === total, `links: explore.html#<sheet id>.<n> opens that exercise, titled as on the sheet (${good}/${total}), linked from index.html`);
}

// ---- 4b. the patches by lines: the DOM after every move equals the markup parsed afresh ----------
// (the page's self-check, window.epureCheckPatches, off in the timed drags above)
{
  const { page, errors } = await open(pagePath);
  await page.evaluate(() => { window.epureCheckPatches = true; });
  const kinds = await page.evaluate(() => window.epure.kinds());
  for (const kind of kinds) {
    await page.click(`#views button[data-kind="${kind}"]`);
    await page.waitForFunction(k => document.querySelector(`#views button[aria-pressed="true"]`)?.dataset.kind === k, {}, kind);
    const handles = await page.evaluate(() => [...document.querySelectorAll("#figure [data-handle]")].map(h => h.dataset.handle));
    for (const id of handles) await mouseDrag(page, `#figure [data-handle="${id}"]`, 12, 5, 4);
  }
  const r = await page.evaluate(() => ({ checked: window.epurePatchesChecked || 0, bad: window.epurePatchErrors || [] }));
  check(r.checked > 100 && r.bad.length === 0 && errors.length === 0,
        `patches: ${r.checked} patches by lines, each equal to the whole markup parsed afresh`, JSON.stringify(r.bad.slice(0, 3)));
  await page.close();
}

// ---- 5. the floor: the same drag on a page whose handler does nothing ----------------------------
// Chrome delivers pointermove aligned to animation frames, so part of *total* is the wait before
// any handler runs. A page with an empty handler (the same figure size, the layout flushed like
// the explorer's) measured the same way gives that part on this machine: what no page can save.
let floor;
{
  const file = path.join(outDir, "floor.html");
  fs.writeFileSync(file, `<!doctype html><meta charset="utf-8"><title>floor</title>
<svg id="figure" width="800" height="600" style="touch-action:none"><circle data-handle="A" cx="400" cy="300" r="8"/></svg>
<script>
  const timings = [];
  let dragging = false;
  const figure = document.getElementById("figure");
  figure.addEventListener("pointerdown", ev => { dragging = true; figure.setPointerCapture(ev.pointerId); });
  figure.addEventListener("pointerup", () => { dragging = false; });
  figure.addEventListener("pointermove", ev => {
    if (!dragging) return;
    const t0 = performance.now();
    figure.getBoundingClientRect();
    const t2 = performance.now();
    timings.push({ total: t2 - ev.timeStamp, handler: t2 - t0 });
  });
  window.epure = { ready: true, timings };
</script>`);
  const { page } = await open(file);
  for (let drag = 0; drag < 40; drag++) await mouseDrag(page, "#figure circle", 12, 3, -2);
  const t = await page.evaluate(() => window.epure.timings);
  floor = { moves: t.length, total_median_ms: quantile(t.map(x => x.total), 0.5), total_p95_ms: quantile(t.map(x => x.total), 0.95),
            handler_median_ms: quantile(t.map(x => x.handler), 0.5), handler_p95_ms: quantile(t.map(x => x.handler), 0.95) };
  await page.close();
}

await browser.close();
const all = Object.values(timings).flatMap(t => [t]);
fs.writeFileSync(path.join(outDir, "timings.json"), JSON.stringify({ ...timings, empty_handler: floor }, null, 2) + "\n");
console.log(`     timing floor (an empty handler, the same drags): ${floor.moves} moves, total median ${floor.total_median_ms.toFixed(2)} ms, ` +
            `p95 ${floor.total_p95_ms.toFixed(2)} ms`);
for (const [kind, t] of Object.entries(timings))
  console.log(`     timing ${kind}: ${t.moves} moves, total median ${t.total_median_ms.toFixed(2)} ms, p95 ${t.total_p95_ms.toFixed(2)} ms; ` +
              `handler median ${t.handler_median_ms.toFixed(2)} ms, p95 ${t.handler_p95_ms.toFixed(2)} ms; core median ${t.core_median_ms.toFixed(2)} ms, p95 ${t.core_p95_ms.toFixed(2)} ms`);
// The target is one frame (p95 <= 16 ms, README); on a loaded two-core CI machine the run checks
// a guard against regressions, EPURE_BROWSER_P95_MS (default 100 ms), and says whether the target held.
const worst = Math.max(...all.map(t => t.total_p95_ms));
const guard = Number(process.env.EPURE_BROWSER_P95_MS || 100);
console.log(`     timing target (p95 <= 16 ms in every view): ${worst <= 16 ? "met" : "NOT met"}, worst p95 ${worst.toFixed(2)} ms`);
check(worst <= guard, `timing: pointer move to updated figure and steps, p95 <= ${guard} ms in every view`, `${worst.toFixed(2)} ms`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
