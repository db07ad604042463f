// Drives the explorer page (postprocess/explore.py) in Debian's chromium through
// playwright-core, which uses the system browser (executablePath) and downloads nothing.
// Usage: node explore_page.mjs PAGE.html CELLS.json OUT.json SHOT.png
//   CELLS.json: [[ix, iy], ...] cells of the default slice to read.
// Writes OUT.json: what the page read (per cell: its flat index, regime, t*, radii and the
// hover read-out), the requests it made that were not file: or data:, its console errors,
// whether a slider and the time slider changed the picture, the load time, and the texts
// the page shows (heading, plot title, tick labels) and any link inside the plot.
import { chromium } from "playwright-core";
import { readFileSync, writeFileSync } from "node:fs";
import { pathToFileURL } from "node:url";

const [page_path, cells_path, out_path, shot_path] = process.argv.slice(2);
const cells = JSON.parse(readFileSync(cells_path, "utf8"));
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
                                        args: ["--no-sandbox", "--disable-gpu"], headless: true });
const out = { requests: [], errors: [], cells: [] };
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 1000 } });
  page.on("request", r => { if (!/^(file|data|blob):/.test(r.url())) out.requests.push(r.url()); });
  page.on("console", m => { if (m.type() === "error") out.errors.push(m.text()); });
  page.on("pageerror", e => out.errors.push(String(e)));
  const t0 = Date.now();
  await page.goto(pathToFileURL(page_path).href);
  await page.evaluate(() => window.explorer.ready);
  out.load_ms = Date.now() - t0;
  // The texts the page shows from the map, as the browser has them (not as markup).
  Object.assign(out, await page.evaluate(() => ({
    heading: document.getElementById("title").textContent,
    plot_title: document.querySelector("#plot .gtitle")?.textContent ?? null,
    plot_ticks: [...document.querySelectorAll("#plot .xtick text, #plot .ytick text")].map(t => t.textContent),
    axis_titles: [...document.querySelectorAll("#plot .g-xtitle, #plot .g-ytitle")].map(t => t.textContent),
    plot_links: [...document.querySelectorAll("#plot a")].map(a => a.getAttribute("href") ?? a.getAttribute("xlink:href"))
      .filter(h => h !== null),
  })));

  // Hover each cell where plotly draws it; the read-out is the page's own.
  for (const [ix, iy] of cells) {
    const box = await page.evaluate(([ix, iy]) => {
      const e = window.explorer, plot = document.getElementById("plot"), L = plot._fullLayout;
      const ax = e.MAP.axes[e.state.x], ay = e.MAP.axes[e.state.y];
      const r = plot.getBoundingClientRect();
      return { x: r.left + L._size.l + L.xaxis.d2p(ax.values[ix]), y: r.top + L._size.t + L.yaxis.d2p(ay.values[iy]) };
    }, [ix, iy]);
    await page.mouse.move(box.x, box.y);
    await page.waitForTimeout(150);
    const read = await page.evaluate(([ix, iy]) => {
      const e = window.explorer, k = e.flatIndex(e.cellIndex(ix, iy));
      return { ix, iy, index: e.cellIndex(ix, iy), flat: k, regime: e.valueAt("regime", k), t_star: e.valueAt("t_star", k),
               command: e.pointCommand(e.cellIndex(ix, iy)),
               a1_inf: e.valueAt("a1_inf", k), a2_inf: e.valueAt("a2_inf", k),
               area_fraction_inf: e.valueAt("area_fraction_inf", k),
               area_fraction: e.data.series.area_fraction ? Array.from(e.data.series.area_fraction.slice(
                 k * e.MAP.time.length, (k + 1) * e.MAP.time.length)) : null,
               touched: e.data.series.touched ? Array.from(e.data.series.touched.slice(
                 k * e.MAP.time.length, (k + 1) * e.MAP.time.length)) : null,
               readout: document.getElementById("readout").textContent };
    }, [ix, iy]);
    out.cells.push(read);
  }
  // Clicking gives the command.
  await page.mouse.click(...Object.values(await page.evaluate(() => {
    const plot = document.getElementById("plot"), r = plot.getBoundingClientRect(), L = plot._fullLayout;
    return { x: r.left + L._size.l + L._size.w / 2, y: r.top + L._size.t + L._size.h / 2 };
  })));
  await page.waitForTimeout(150);
  out.command = await page.evaluate(() => document.getElementById("command").textContent);
  // The lines drawn over the heat map (h_0, h_inf, a design window's edges), as plotly has them.
  out.lines = await page.evaluate(() => document.getElementById("plot").data
    .filter(t => t.type === "scatter" && t.mode === "lines").map(t => ({ name: t.name, x: Array.from(t.x), y: Array.from(t.y) })));

  const picture = () => page.evaluate(() => JSON.stringify(document.getElementById("plot").data.map(t => t.z)));
  // A slider of another axis moves the slice.
  const slider = await page.$("input[id^=slider-]:not(#slider-time)");
  out.slider = null;
  if (slider) {
    const before = await picture();
    await slider.evaluate(r => { r.value = r.max; r.dispatchEvent(new Event("input")); });
    out.slider = { id: await slider.evaluate(r => r.id), changed: before !== await picture() };
    await slider.evaluate(r => { r.value = 0; r.dispatchEvent(new Event("input")); });
  }
  // The time slider moves a series.
  out.time_slider = null;
  if (await page.$("#slider-time")) {
    // a2 on a regime map; a surface map's first series (the caps touched).
    const colours = await page.$$eval("#colour option", os => os.map(o => o.value));
    await page.selectOption("#colour", colours.includes("a2") ? "a2" : colours[1]);
    const before = await picture();
    await page.$eval("#slider-time", r => { r.value = r.max; r.dispatchEvent(new Event("input")); });
    out.time_slider = { changed: before !== await picture() };
    await page.selectOption("#colour", "regime");
  }
  await page.screenshot({ path: shot_path, fullPage: false });
} finally {
  await browser.close();
}
writeFileSync(out_path, JSON.stringify(out, null, 1));
