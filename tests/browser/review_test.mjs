// epure scan's review page in headless Chromium (Debian's chromium, puppeteer-core).
//   node review_test.mjs REVIEW_HTML FIELDS_CSV OUT_DIR
// Checks the page as a teacher uses it: every field sent to review listed with its crop and the
// value proposed, in the set's language; no request outside the file; the keyboard moves through
// the fields (Enter and ↓ forward, ↑ back); typed values saved by Ctrl+S as OUT_DIR/corrections.json
// in the corrections file's format. Prints one line per check, then "N passed, M failed".
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import puppeteer from "puppeteer-core";

const [reviewPath, fieldsCsv, outDir] = process.argv.slice(2);
fs.mkdirSync(outDir, { recursive: true });
let passed = 0, failed = 0;
function check(ok, what, detail = "") {
  if (ok) passed++;
  else failed++;
  console.log(`${ok ? "ok  " : "FAIL"} ${what}${detail ? ": " + detail : ""}`);
}

// the fields scan sent to review, from fields.csv (sheet,page,question,status,…)
const toReview = fs.readFileSync(fieldsCsv, "utf8").trim().split("\n").slice(1)
  .map(l => l.split(",")).filter(c => c[3] === "review").map(c => `${c[0]} ${c[2]}`);

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu"],
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 900 });
  const url = pathToFileURL(path.resolve(reviewPath)).href;
  const refused = [], errors = [];
  await page.setRequestInterception(true);
  page.on("request", req => {
    const u = req.url();
    if (u === url || u.startsWith("data:") || u.startsWith("blob:")) req.continue();
    else { refused.push(u); req.abort(); }
  });
  page.on("console", msg => { if (msg.type() === "error") errors.push(msg.text()); });
  page.on("pageerror", err => errors.push(String(err)));
  const cdp = await page.target().createCDPSession();
  await cdp.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: path.resolve(outDir) });
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => window.epureReview !== undefined, { timeout: 10000 });

  const listed = await page.evaluate(() => window.epureReview.fields().map(f => `${f.sheet} ${f.question}`));
  check(listed.length === toReview.length && listed.every(x => toReview.includes(x)),
        "every field sent to review is listed", `${listed.length} listed, ${toReview.length} in fields.csv`);
  check(listed.length >= 3, "the test set has fields to review", String(listed.length));
  const lang = await page.evaluate(() => document.documentElement.lang);
  const title = await page.title();
  check(lang === "fr" && title.includes("vérifier"), "in the set's language", `${lang}: ${title}`);
  const crops = await page.$$eval("img.crop", imgs => imgs.map(i => i.complete && i.naturalWidth > 20 && i.naturalHeight > 10));
  check(crops.length === listed.length && crops.every(Boolean), "every field shows its crop", `${crops.filter(Boolean).length}/${crops.length}`);
  const proposed = await page.$$eval("input.value", ins => ins.map(i => i.value));
  const expectedProposals = await page.evaluate(() => window.epureReview.fields().map(f => f.proposed));
  check(JSON.stringify(proposed) === JSON.stringify(expectedProposals), "each box holds the value proposed");

  // the keyboard: the first field has the focus; Enter and ↓ move on, ↑ goes back
  const focused = () => page.evaluate(() => document.activeElement && document.activeElement.dataset.index);
  check(await focused() === "0", "the first field has the focus");
  await page.keyboard.press("Enter");
  check(await focused() === "1", "Enter moves to the next field");
  await page.keyboard.press("ArrowDown");
  check(await focused() === "2", "↓ moves to the next field");
  await page.keyboard.press("ArrowUp");
  check(await focused() === "1", "↑ goes back");
  // type a value in each field, moving with Enter: field i gets "1" + i (a blank for the last)
  await page.evaluate(() => window.epureReview.go(0));
  const typed = [];
  for (let i = 0; i < listed.length; i++) {
    const v = i === listed.length - 1 ? "" : `1${i}`;
    await page.keyboard.down("Control");
    await page.keyboard.press("a");
    await page.keyboard.up("Control");
    await page.keyboard.press("Backspace");
    if (v) await page.keyboard.type(v);
    typed.push(v);
    await page.keyboard.press("Enter");
  }
  const progress = await page.$eval("#progress", e => e.textContent);
  check(progress.startsWith(`${listed.length} sur ${listed.length}`), "progress counts the fields visited", progress);

  // Ctrl+S saves corrections.json
  const saved = path.join(outDir, "corrections.json");
  if (fs.existsSync(saved)) fs.unlinkSync(saved);
  await page.keyboard.down("Control");
  await page.keyboard.press("s");
  await page.keyboard.up("Control");
  for (let t = 0; t < 50 && !fs.existsSync(saved); t++) await new Promise(r => setTimeout(r, 100));
  check(fs.existsSync(saved), "Ctrl+S saves corrections.json");
  if (fs.existsSync(saved)) {
    const c = JSON.parse(fs.readFileSync(saved, "utf8"));
    check(c.format === "epure-corrections" && c.version === 1 && Array.isArray(c.corrections), "in the corrections file's format");
    check(c.corrections.length === listed.length &&
          c.corrections.every((k, i) => `${k.sheet} ${k.question}` === listed[i] && k.value === typed[i]),
          "every field's typed value saved", JSON.stringify(c.corrections.slice(0, 2)));
  }
  await page.screenshot({ path: path.join(outDir, "review.png") });
  check(refused.length === 0, "no request outside the page", refused.join(" "));
  check(errors.length === 0, "no console error", errors.join(" | "));
} finally {
  await browser.close();
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
