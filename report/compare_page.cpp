#include "report/compare_page.hpp"

#include <cmath>
#include <filesystem>
#include <map>

#include "common/errors.hpp"
#include "diagnosis/diagnose.hpp"
#include "dtwin/uplot_assets.hpp"
#include "report/study_report.hpp"

namespace dtwin {

namespace {

/// What the page draws of one series of compare.json.
nlohmann::json slimSeries(const nlohmann::json& s) {
  nlohmann::json c{
      {"channel", s.at("channel")},
      {"unit", s.value("unit", "")},
      {"fit", s.value("fit_percent", nlohmann::json())},
      {"baseline_fit", s.value("baseline_fit_percent", nlohmann::json())},
      {"rms", s.value("rms", nlohmann::json())},
      {"coverage", s.value("coverage95", nlohmann::json())},
      {"noise_sd", s.contains("noise_variance") && s.at("noise_variance").is_number()
                       ? nlohmann::json(std::sqrt(s.at("noise_variance").get<double>()))
                       : nlohmann::json()},
      {"t", s.at("t")},
      {"y", s.at("measured_mean")},
      {"models", nlohmann::json::array()},
      {"windows", nlohmann::json::array()},
      {"bands", s.value("bands", nlohmann::json::array())},
      {"bands_note", s.value("bands_note", "")},
      {"frf", s.value("frequency_response", nlohmann::json())},
      {"windows_note", s.value("windows_note", "")}};
  if (s.contains("discrepancy")) {  // twin compare --discrepancy: the filter and the three fits
    const auto& d = s.at("discrepancy");
    c["discrepancy"] = {{"physics_fit", d.value("physics_fit_percent", nlohmann::json())},
                        {"hybrid_fit", d.value("hybrid_fit_percent", nlohmann::json())},
                        {"baseline_fit", d.value("baseline_fit_percent", nlohmann::json())},
                        {"share", d.value("share", nlohmann::json())},
                        {"none", d.value("none", false)},
                        {"description", d.value("description", "")},
                        {"summary", d.value("summary", "")},
                        {"note", d.value("response_note", "")},
                        {"bands", d.value("bands", nlohmann::json::array())},
                        {"response", d.value("response", nlohmann::json::object())}};
  }
  for (const auto& w : s.value("windows", nlohmann::json::array()))
    c["windows"].push_back({{"t0", w.at("t_begin_s")},
                            {"t1", w.at("t_end_s")},
                            {"z", w.at("peak_z")},
                            {"share", w.at("share_of_chi2")},
                            {"label", w.value("label", "")}});
  return c;
}

/// The JSON text made safe inside a <script> element.
std::string scriptSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += json[i];
    }
  }
  return out;
}

// The page's script: one group of stacked charts per data set (value and residual per channel),
// linked zoom, one cursor, min/max decimation per pixel column for display, the failing windows
// shaded and tabled (largest share first, under each channel's windows in words), the spectrum
// per band. `#selftest` in the URL writes what a test checks into <pre id="selftest"> (chart
// count, window rows and their shares, the windows' notes, the discrepancy sections' charts and
// fits, errors, whether a zoom moved every chart).
constexpr const char* kScript = R"js(
"use strict";
const errors = [];
window.addEventListener("error", e => errors.push(String(e.message)));
const D = JSON.parse(document.getElementById("data").textContent);
const groups = [];
const palette = ["#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"];
const units = { mps2: "m/s²", mps: "m/s", m: "m", N: "N", rad: "rad", radps: "rad/s" };
const fmt = v => (v == null || !isFinite(v)) ? "–" : Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : (+v.toPrecision(5)).toString();
function lowerBound(a, x) { let lo = 0, hi = a.length; while (lo < hi) { const m = (lo + hi) >> 1; if (a[m] < x) lo = m + 1; else hi = m; } return lo; }
// Min and max per pixel column of the samples in [lo, hi], each series on its own, in time order:
// what is drawn; the numbers (legend, tables) are the full series.
function decimate(full, lo, hi, width) {
  const t = full[0];
  let a = Math.max(0, lowerBound(t, lo) - 1), b = Math.min(t.length, lowerBound(t, hi) + 1);
  const cols = Math.max(1, Math.floor(width)), n = b - a;
  if (n <= 2 * cols) return full.map(s => s.slice(a, b));
  const out = full.map(() => []), per = n / cols;
  for (let c = 0; c < cols; c++) {
    const i0 = a + Math.floor(c * per), i1 = Math.min(b, a + Math.floor((c + 1) * per));
    if (i1 <= i0) continue;
    out[0].push(t[i0], t[i1 - 1]);
    for (let k = 1; k < full.length; k++) {
      const s = full[k];
      let mn = Infinity, mx = -Infinity, imn = i0, imx = i0;
      let gap = false;
      for (let i = i0; i < i1; i++) { const v = s[i]; if (v === null) { gap = true; continue; } if (v < mn) { mn = v; imn = i; } if (v > mx) { mx = v; imx = i; } }
      if (mn === Infinity) out[k].push(null, null);
      else if (gap) out[k].push(mn === mx ? mn : null, null);
      else if (imn <= imx) out[k].push(mn, mx); else out[k].push(mx, mn);
    }
  }
  return out;
}
function zoomTo(g, min, max) {
  if (!(max > min)) return;
  g.range = [min, max];
  for (const c of g.charts) {
    c.u.setData(decimate(c.full, min, max, c.u.bbox.width / devicePixelRatio), false);
    c.u.setScale("x", { min, max });
  }
}
function shade(windows) {
  return u => {
    const ctx = u.ctx, top = u.bbox.top, h = u.bbox.height;
    ctx.save();
    ctx.fillStyle = "rgba(220, 50, 47, 0.18)";
    for (const w of windows) {
      const x0 = u.valToPos(w.t0, "x", true), x1 = u.valToPos(w.t1, "x", true);
      if (x1 < u.bbox.left || x0 > u.bbox.left + u.bbox.width) continue;
      ctx.fillRect(Math.min(x0, x1 - 2), top, Math.max(x1 - x0, 4), h);
    }
    ctx.restore();
  };
}
function chart(g, el, title, unit, series, full, windows, height, bands) {
  const opts = {
    title, width: Math.max(300, el.clientWidth), height,
    scales: { x: { time: false } },
    axes: [{ label: "time [s]" }, { label: unit, size: 70 }],
    series: [{ label: "t [s]", value: (u, v) => fmt(v) }].concat(series),
    bands: bands || [],
    cursor: { sync: { key: g.key }, drag: { x: true, y: false, setScale: false },
              bind: { dblclick: () => () => { zoomTo(g, g.full[0], g.full[1]); return null; } } },
    hooks: { draw: [shade(windows)],
             setSelect: [u => { if (u.select.width > 2) { const a = u.posToVal(u.select.left, "x"), b = u.posToVal(u.select.left + u.select.width, "x");
                                 u.setSelect({ left: 0, width: 0, top: 0, height: 0 }, false); zoomTo(g, a, b); } }] },
  };
  const u = new uPlot(opts, decimate(full, g.full[0], g.full[1], opts.width), el);
  g.charts.push({ u, full });
}
// Text made safe inside HTML or SVG markup (element content and quoted attributes).
function esc(s) { return String(s == null ? "" : s).replace(/[&<>"']/g, ch => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[ch]); }
// A tick of a log axis: 0.5, 1, 20, 1000; 10⁵ and 10⁻⁴ beyond.
function logTick(v) {
  const e = Math.round(Math.log10(v));
  if ((e > 4 || e < -3) && Math.abs(v / Math.pow(10, e) - 1) < 1e-9)
    return "10" + String(e).replace(/[-0-9]/g, d => "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"["-0123456789".indexOf(d)]);
  return String(+v.toPrecision(3));
}
// The residual's spectrum per band as an inline SVG: residual power / noise power on a log axis
// against frequency on a log axis, one bar per band spanning lo_hz..hi_hz, the noise floor (ratio 1)
// dashed, failing bands red, the others blue; "" when no band has a usable frequency range.
function spectrumSvg(c) {
  const B = c.bands.filter(b => b.lo_hz > 0 && b.hi_hz > b.lo_hz);
  if (!B.length) return "";
  const W = 580, H = 250, L = 62, R = 72, T = 34, Bm = 42, pw = W - L - R, ph = H - T - Bm;
  const f0 = Math.min(...B.map(b => b.lo_hz)), f1 = Math.max(...B.map(b => b.hi_hz));
  const rs = B.map(b => b.ratio).filter(r => r > 0 && isFinite(r));
  const y0 = Math.pow(10, Math.floor(Math.log10(Math.min(1, ...rs) / 1.5))), y1 = Math.pow(10, Math.ceil(Math.log10(Math.max(1, ...rs) * 1.5)));
  const X = f => L + pw * Math.log10(f / f0) / Math.log10(f1 / f0), Y = r => T + ph * (1 - Math.log10(r / y0) / Math.log10(y1 / y0));
  const px = v => v.toFixed(1);
  let s = "<svg class=spectrum-chart xmlns='http://www.w3.org/2000/svg' width=" + W + " height=" + H + " viewBox='0 0 " + W + " " + H + "' font-size=11 fill='#333'>";
  s += "<text x=" + L + " y=15 font-size=13 font-weight=bold>" + esc(c.channel) + " residual spectrum</text>";
  s += "<rect x=" + (L + pw - 196) + " y=7 width=10 height=10 fill='#d62728'/><text x=" + (L + pw - 182) + " y=16>fails (1 % test)</text>" +
       "<rect x=" + (L + pw - 84) + " y=7 width=10 height=10 fill='#1f77b4'/><text x=" + (L + pw - 70) + " y=16>within noise</text>";
  // Ratio axis: a gridline and label per decade (every k-th past 8 decades), minor gridlines at 2..9 up to 4 decades.
  const e0 = Math.round(Math.log10(y0)), e1 = Math.round(Math.log10(y1)), k = Math.max(1, Math.ceil((e1 - e0) / 8));
  for (let e = e0; e <= e1; e++) {
    const v = Math.pow(10, e), y = px(Y(v));
    if (e1 - e0 <= 4 && e < e1) for (let m = 2; m <= 9; m++) s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + px(Y(m * v)) + " y2=" + px(Y(m * v)) + " stroke='#f0f0f0'/>";
    if ((e - e0) % k) continue;
    s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#ddd'/>";
    s += "<text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + logTick(v) + "</text>";
  }
  // Frequency axis: 1-2-5 ticks (the ends if fewer than two fall inside).
  let xt = [];
  for (let e = Math.floor(Math.log10(f0)); e <= Math.ceil(Math.log10(f1)); e++)
    for (const m of [1, 2, 5]) { const v = m * Math.pow(10, e); if (v >= f0 * (1 - 1e-9) && v <= f1 * (1 + 1e-9)) xt.push(v); }
  if (xt.length < 2) xt = [f0, f1];
  for (const v of xt) {
    const x = px(X(v));
    s += "<line x1=" + x + " x2=" + x + " y1=" + T + " y2=" + (T + ph) + " stroke='#eee'/><line x1=" + x + " x2=" + x + " y1=" + (T + ph) + " y2=" + (T + ph + 4) + " stroke='#666'/>";
    s += "<text x=" + x + " y=" + (T + ph + 16) + " text-anchor=middle>" + logTick(v) + "</text>";
  }
  // One bar per band from the axis up to its ratio, the ratio written above it.
  for (const b of B) {
    const col = b.significant ? "#d62728" : "#1f77b4", x0 = X(b.lo_hz) + 1, x1 = X(b.hi_hz) - 1, ok = b.ratio > 0 && isFinite(b.ratio);
    const tip = esc(b.band + ": " + fmt(b.lo_hz) + "–" + fmt(b.hi_hz) + " Hz, residual / noise power " + fmt(b.ratio) + (b.significant ? ", fails" : ""));
    if (ok) {
      const yt = Y(b.ratio);
      s += "<rect x=" + px(x0) + " y=" + px(yt) + " width=" + px(Math.max(1, x1 - x0)) + " height=" + px(T + ph - yt) + " fill='" + col + "' fill-opacity=0.3><title>" + tip + "</title></rect>";
      s += "<line x1=" + px(x0) + " x2=" + px(x1) + " y1=" + px(yt) + " y2=" + px(yt) + " stroke='" + col + "' stroke-width='2.5'/>";
      s += "<text x=" + px((x0 + x1) / 2) + " y=" + px(yt - 5) + " text-anchor=middle font-weight=bold stroke='#fff' stroke-width=3 paint-order=stroke fill='" + col + "'>" + esc(fmt(b.ratio)) + "</text>";
    }
    if (x1 - x0 > 6.5 * String(b.band).length + 6 && !(ok && Y(b.ratio) > T + ph - 24))  // not under a low bar's figure
      s += "<text x=" + px((x0 + x1) / 2) + " y=" + (T + ph - 6) + " text-anchor=middle font-size=10 fill='#555'>" + esc(b.band) + "</text>";
  }
  // The noise floor: ratio 1, named right of the plot.
  const yn = px(Y(1));
  s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + yn + " y2=" + yn + " stroke='#222' stroke-width=1.2 stroke-dasharray='6 4'/>";
  s += "<text x=" + (L + pw + 5) + " y=" + yn + " dy=4 fill='#222'>noise floor</text>";
  s += "<rect x=" + L + " y=" + T + " width=" + pw + " height=" + ph + " fill=none stroke='#999'/>";
  s += "<text x=" + (L + pw / 2) + " y=" + (H - 6) + " text-anchor=middle>frequency [Hz]</text>";
  s += "<text transform='translate(14 " + (T + ph / 2) + ") rotate(-90)' text-anchor=middle>residual power / noise power</text>";
  return s + "</svg>";
}
// The spectrum per band: the chart and, beside it, its figures; the note when there is no spectrum.
function bandsTable(c) {
  if (!c.bands.length) return c.bands_note ? "<p class=note>spectrum: " + esc(c.bands_note) + "</p>" : "";
  let h = "<table class=bands><tr><th>band</th><th>Hz</th><th>residual /<br>noise power</th><th></th></tr>";
  for (const b of c.bands)
    h += "<tr class=" + (b.significant ? "fail" : "ok") + "><td>" + esc(b.band) + "</td><td>" + esc(fmt(b.lo_hz) + "–" + fmt(b.hi_hz)) +
         "</td><td class=num>" + esc(fmt(b.ratio)) + "</td><td>" + (b.significant ? "fails" : "") + "</td></tr>";
  return "<div class=spectrum>" + spectrumSvg(c) + h + "</table></div>" + (c.bands_note ? "<p class=note>spectrum: " + esc(c.bands_note) + "</p>" : "");
}
// What the physics misses, as a filter (twin compare --discrepancy): the three fit percentages side
// by side, the filter's share, the car's response over the model's (gain and phase against
// frequency, each band's figure as a bar across it) and the bands in words.
function discrepancySvg(d) {
  const r = d.response || {}, F = r.freq_hz || [];
  if (F.length < 2) return "";
  const W = 580, H = 300, L = 62, R = 72, T = 30, gap = 34, Bm = 40, pw = W - L - R, ph = (H - T - gap - Bm) / 2;
  const f0 = F[0], f1 = F[F.length - 1];
  const X = f => L + pw * Math.log10(f / f0) / Math.log10(f1 / f0);
  const gmax = Math.max(2, ...r.gain.filter(isFinite)), g1 = Math.pow(2, Math.ceil(Math.log2(gmax))), g0 = 1 / g1;
  const Yg = g => T + ph * (1 - (Math.log2(Math.min(g1, Math.max(g0, g))) - Math.log2(g0)) / (Math.log2(g1) - Math.log2(g0)));
  const Yp = p => T + ph + gap + ph * (1 - (Math.max(-180, Math.min(180, p)) + 180) / 360);
  const px = v => v.toFixed(1);
  let s = "<svg class=discrepancy-chart xmlns='http://www.w3.org/2000/svg' width=" + W + " height=" + H + " viewBox='0 0 " + W + " " + H + "' font-size=11 fill='#333'>";
  s += "<text x=" + L + " y=15 font-size=13 font-weight=bold>the car over the model: gain and phase</text>";
  for (const [y0, lab] of [[T, "gain (×)"], [T + ph + gap, "phase [°]"]]) {
    s += "<rect x=" + L + " y=" + y0 + " width=" + pw + " height=" + px(ph) + " fill=none stroke='#999'/>";
    s += "<text transform='translate(14 " + px(y0 + ph / 2) + ") rotate(-90)' text-anchor=middle>" + lab + "</text>";
  }
  for (let e = Math.log2(g0); e <= Math.log2(g1); e++) {
    const v = Math.pow(2, e), y = px(Yg(v));
    s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#eee'/><text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + logTick(v) + "</text>";
  }
  for (const v of [-180, -90, 0, 90, 180]) {
    const y = px(Yp(v));
    s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#eee'/><text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + v + "</text>";
  }
  let xt = [];
  for (let e = Math.floor(Math.log10(f0)); e <= Math.ceil(Math.log10(f1)); e++)
    for (const m of [1, 2, 5]) { const v = m * Math.pow(10, e); if (v >= f0 * (1 - 1e-9) && v <= f1 * (1 + 1e-9)) xt.push(v); }
  for (const v of xt) {
    const x = px(X(v));
    s += "<line x1=" + x + " x2=" + x + " y1=" + T + " y2=" + px(T + 2 * ph + gap) + " stroke='#f0f0f0'/>";
    s += "<text x=" + x + " y=" + px(T + 2 * ph + gap + 16) + " text-anchor=middle>" + logTick(v) + "</text>";
  }
  // The model: gain 1, phase 0 (dashed); the car per bin (line); each band's figure (a bar across it).
  s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + px(Yg(1)) + " y2=" + px(Yg(1)) + " stroke='#222' stroke-dasharray='6 4'/>";
  s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + px(Yp(0)) + " y2=" + px(Yp(0)) + " stroke='#222' stroke-dasharray='6 4'/>";
  s += "<text x=" + (L + pw + 5) + " y=" + px(Yg(1)) + " dy=4>the model</text><text x=" + (L + pw + 5) + " y=" + px(Yp(0)) + " dy=4>the model</text>";
  s += "<polyline fill=none stroke='#9467bd' stroke-width=1.3 points='" + F.map((f, i) => px(X(f)) + "," + px(Yg(r.gain[i]))).join(" ") + "'/>";
  s += "<polyline fill=none stroke='#9467bd' stroke-width=1.3 points='" + F.map((f, i) => px(X(f)) + "," + px(Yp(r.phase_deg[i]))).join(" ") + "'/>";
  for (const b of d.bands || []) {
    if (!b.read) continue;
    const x0 = X(Math.max(f0, b.lo_hz)), x1 = X(Math.min(f1, b.hi_hz));
    if (!(x1 > x0)) continue;
    const tip = "<title>" + esc(b.words) + "</title>";
    s += "<line x1=" + px(x0) + " x2=" + px(x1) + " y1=" + px(Yg(b.gain)) + " y2=" + px(Yg(b.gain)) + " stroke='#d62728' stroke-width=3>" + tip + "</line>";
    s += "<line x1=" + px(x0) + " x2=" + px(x1) + " y1=" + px(Yp(b.phase_deg)) + " y2=" + px(Yp(b.phase_deg)) + " stroke='#d62728' stroke-width=3>" + tip + "</line>";
    s += "<text x=" + px((x0 + x1) / 2) + " y=" + px(Yg(b.gain) - 5) + " text-anchor=middle font-weight=bold stroke='#fff' stroke-width=3 paint-order=stroke fill='#d62728'>" + esc(fmt(+b.gain.toPrecision(2))) + "×</text>";
    s += "<text x=" + px((x0 + x1) / 2) + " y=" + px(Yp(b.phase_deg) - 5) + " text-anchor=middle font-weight=bold stroke='#fff' stroke-width=3 paint-order=stroke fill='#d62728'>" + esc(Math.round(b.phase_deg)) + "°</text>";
  }
  s += "<text x=" + (L + pw / 2) + " y=" + (H - 6) + " text-anchor=middle>frequency [Hz]</text>";
  return s + "</svg>";
}
function discrepancySection(c) {
  const d = c.discrepancy, pct = v => v != null && isFinite(v) ? (+v).toFixed(1) + " %" : "–";
  let h = "<div class=discrepancy id=\"discrepancy-" + esc(c.channel) + "\"><h3>" + esc(c.channel) + ": what the physics misses, as a filter</h3>";
  h += "<table class=fits><tr><th>on this drive</th><th>fit</th></tr><tr><td>physics alone (the headline)</td><td class=num>" + pct(d.physics_fit) +
       "</td></tr><tr><td>physics + filter</td><td class=num>" + pct(d.hybrid_fit) + "</td></tr><tr><td>FIR baseline</td><td class=num>" + pct(d.baseline_fit) +
       "</td></tr><tr><td>the filter's share of the prediction</td><td class=num>" + (d.share != null && isFinite(d.share) ? (100 * d.share).toFixed(0) + " %" : "–") + "</td></tr></table>";
  h += "<p class=reading>" + esc(d.summary) + "</p>";
  h += "<div class=spectrum>" + discrepancySvg(d) + "</div>";
  h += "<p class=note>" + esc(d.description) + (d.note ? "; response " + esc(d.note) : "") + ". A prediction aid, not physics: it names no cause.</p></div>";
  return h;
}
// The frequency response from the road to the channel as an inline SVG: magnitude (log-log),
// phase and, beneath, the coherence, against log frequency; measured black with its 95 % band grey,
// predicted blue; the bands where they differ at 95 % shaded red. Beside it the bands' gain ratio
// and phase difference, measured over predicted; the note when there is none.
function frfSvg(c) {
  const R = c.frf, f = R.f_hz, M = R.measured, P = R.predicted, unit = units[c.unit] || c.unit;
  const K = []; for (let k = 1; k < f.length; k++) K.push(k);
  const W = 580, L = 62, Rm = 16, pw = W - L - Rm, T = 34, gap = 14, hm = 150, hp = 90, hc = 64, Bm = 38;
  const H = T + hm + gap + hp + gap + hc + Bm, f0 = f[1], f1 = f[f.length - 1];
  const X = v => L + pw * Math.log10(v / f0) / Math.log10(f1 / f0), px = v => v.toFixed(1);
  const mags = K.map(k => M.magnitude[k]).concat(K.map(k => P.magnitude[k])).filter(v => v > 0 && isFinite(v));
  if (!mags.length) return "";
  const m1 = Math.pow(10, Math.ceil(Math.log10(Math.max(...mags) * 1.2))), m0 = Math.max(Math.pow(10, Math.floor(Math.log10(Math.min(...mags)))), m1 * 1e-4);
  const t1 = T + hm + gap, t2 = t1 + hp + gap;
  const Ym = v => T + hm * (1 - Math.log10(Math.min(m1, Math.max(m0, v)) / m0) / Math.log10(m1 / m0));
  const Yp = v => t1 + hp * (1 - (v + 180) / 360), Yc = v => t2 + hc * (1 - v);
  let s = "<svg class=frf-chart xmlns='http://www.w3.org/2000/svg' width=" + W + " height=" + H + " viewBox='0 0 " + W + " " + H + "' font-size=11 fill='#333'>";
  s += "<text x=" + L + " y=15 font-size=13 font-weight=bold>" + esc(c.channel) + " frequency response from " + esc(R.input) + "</text>";
  s += "<line x1=" + (L + pw - 232) + " x2=" + (L + pw - 216) + " y1=25 y2=25 stroke='#222' stroke-width='1.5'/><text x=" + (L + pw - 211) + " y=29>measured</text>" +
       "<line x1=" + (L + pw - 146) + " x2=" + (L + pw - 130) + " y1=25 y2=25 stroke='#1f77b4' stroke-width='1.5'/><text x=" + (L + pw - 125) + " y=29>predicted</text>" +
       "<rect x=" + (L + pw - 56) + " y=20 width=10 height=10 fill='rgba(220,50,47,0.25)'/><text x=" + (L + pw - 42) + " y=29>differs</text>";
  // The bands that differ, shaded over the three panels.
  for (const b of R.bands || []) if (b.differs) {
    const x0 = X(Math.max(f0, b.lo_hz)), x1 = X(Math.min(f1, b.hi_hz));
    const tip = esc(b.band + ": gain ratio " + fmt(b.gain_ratio) + ", phase difference " + fmt(b.phase_difference_deg) + "°");
    for (const [y, h] of [[T, hm], [t1, hp], [t2, hc]])
      s += "<rect x=" + px(x0) + " y=" + y + " width=" + px(Math.max(1, x1 - x0)) + " height=" + h + " fill='rgba(220,50,47,0.15)'><title>" + tip + "</title></rect>";
  }
  // Frequency gridlines (1-2-5) on every panel, labels under the last.
  const xt = [];
  for (let e = Math.floor(Math.log10(f0)); e <= Math.ceil(Math.log10(f1)); e++)
    for (const m of [1, 2, 5]) { const v = m * Math.pow(10, e); if (v >= f0 * (1 - 1e-9) && v <= f1 * (1 + 1e-9)) xt.push(v); }
  for (const v of xt) {
    const x = px(X(v));
    for (const [y, h] of [[T, hm], [t1, hp], [t2, hc]]) s += "<line x1=" + x + " x2=" + x + " y1=" + y + " y2=" + (y + h) + " stroke='#eee'/>";
    s += "<text x=" + x + " y=" + (t2 + hc + 15) + " text-anchor=middle>" + logTick(v) + "</text>";
  }
  for (let e = Math.round(Math.log10(m0)); e <= Math.round(Math.log10(m1)); e++) {
    const y = px(Ym(Math.pow(10, e)));
    s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#ddd'/><text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + logTick(Math.pow(10, e)) + "</text>";
  }
  for (const v of [-180, -90, 0, 90, 180]) { const y = px(Yp(v)); s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#ddd'/><text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + v + "°</text>"; }
  for (const v of [0, 0.5, 1]) { const y = px(Yc(v)); s += "<line x1=" + L + " x2=" + (L + pw) + " y1=" + y + " y2=" + y + " stroke='#ddd'/><text x=" + (L - 6) + " y=" + y + " dy=4 text-anchor=end>" + v + "</text>"; }
  // The measured 95 % bands: |H| exp(±1.96 ε) and φ ± 1.96 σ_φ.
  const area = (lo, hi) => { const a = K.filter(k => isFinite(lo(k)) && isFinite(hi(k))); if (!a.length) return "";
    return "<path d='M" + a.map(k => px(X(f[k])) + " " + px(hi(k))).join("L") + "L" + a.slice().reverse().map(k => px(X(f[k])) + " " + px(lo(k))).join("L") + "Z' fill='rgba(0,0,0,0.10)'/>"; };
  const eps = k => Math.min(5, isFinite(M.magnitude_error[k]) ? M.magnitude_error[k] : 5);
  s += area(k => Ym(M.magnitude[k] * Math.exp(-1.96 * eps(k))), k => Ym(M.magnitude[k] * Math.exp(1.96 * eps(k))));
  // Lines; the phase broken where it wraps.
  const line = (val, Y, col, wraps) => { let d = "", prev = null;
    for (const k of K) { const v = val[k]; if (v == null || !isFinite(v)) { prev = null; continue; }
      d += (prev === null || (wraps && Math.abs(v - prev) > 180) ? "M" : "L") + px(X(f[k])) + " " + px(Y(v)); prev = v; }
    return "<path d='" + d + "' fill=none stroke='" + col + "' stroke-width='1.3'/>"; };
  s += line(M.magnitude, Ym, "#222") + line(P.magnitude, Ym, "#1f77b4");
  s += line(M.phase_deg, Yp, "#222", true) + line(P.phase_deg, Yp, "#1f77b4", true);
  s += line(M.coherence, Yc, "#222") + line(P.coherence, Yc, "#1f77b4");
  for (const [y, h] of [[T, hm], [t1, hp], [t2, hc]]) s += "<rect x=" + L + " y=" + y + " width=" + pw + " height=" + h + " fill=none stroke='#999'/>";
  const ylab = (y, h, t) => "<text transform='translate(14 " + (y + h / 2) + ") rotate(-90)' text-anchor=middle>" + esc(t) + "</text>";
  s += ylab(T, hm, "gain [" + unit + " / m]") + ylab(t1, hp, "phase") + ylab(t2, hc, "coherence γ²");
  s += "<text x=" + (L + pw / 2) + " y=" + (H - 6) + " text-anchor=middle>frequency [Hz]</text>";
  return s + "</svg>";
}
// v ± sd with sd to two significant digits and v to the same decimals.
function pm(v, sd) {
  if (!(sd > 0) || !isFinite(sd)) return fmt(v);
  const d = Math.min(8, Math.max(0, 1 - Math.floor(Math.log10(sd))));
  return (+v).toFixed(d) + " ± " + (+sd).toFixed(d);
}
function frfTable(c) {
  const R = c.frf;
  if (!R || !R.f_hz) return R && R.note ? "<p class=note>frequency response: " + esc(R.note) + "</p>" : "";
  let h = "<table class=bands><tr><th>band</th><th>Hz</th><th>gain ratio<br>measured / predicted</th><th>phase<br>difference</th><th></th></tr>";
  for (const b of R.bands)
    h += "<tr class=" + (b.differs ? "fail" : "ok") + "><td>" + esc(b.band) + "</td><td>" + esc(fmt(b.lo_hz) + "–" + fmt(b.hi_hz)) + "</td><td class=num>" +
         esc(pm(b.gain_ratio, b.gain_ratio * b.gain_ratio_error)) + "</td><td class=num>" +
         esc((+b.phase_difference_deg).toFixed(1) + "° ± " + (+b.phase_difference_sd_deg).toFixed(1) + "°") + "</td><td>" + (b.differs ? "differs" : "") + "</td></tr>";
  return "<div class=spectrum>" + frfSvg(c) + h + "</table></div>" + (R.note ? "<p class=note>frequency response: " + esc(R.note) + "</p>" : "");
}
function build() {
  const root = document.getElementById("sets");
  D.sets.forEach((set, gi) => {
    const sec = document.createElement("section");
    root.appendChild(sec);
    const h = document.createElement("h2");
    h.textContent = set.name + " @ " + set.scenario;
    sec.appendChild(h);
    const lay = document.createElement("div"); lay.className = "layout"; sec.appendChild(lay);
    const plots = document.createElement("div"); plots.className = "plots"; lay.appendChild(plots);
    const side = document.createElement("div"); side.className = "side"; lay.appendChild(side);
    if (D.no_windows) side.style.display = "none";
    let tmin = Infinity, tmax = -Infinity;
    for (const c of set.channels) { if (c.t.length) { tmin = Math.min(tmin, c.t[0]); tmax = Math.max(tmax, c.t[c.t.length - 1]); } }
    const g = { key: "set" + gi, charts: [], full: [tmin, tmax], range: [tmin, tmax] };
    groups.push(g);
    const nav = document.createElement("div"); nav.className = "nav";
    nav.innerHTML = "<button data-a=left>◀ pan</button><button data-a=out>zoom out</button><button data-a=right>pan ▶</button><button data-a=all>" + (D.whole || "whole drive") + "</button>" +
                    "<span class=hint>drag across a plot to zoom; double-click for the " + (D.whole || "whole drive") + "</span>";
    nav.addEventListener("click", e => {
      const a = e.target.dataset.a; if (!a) return;
      const [lo, hi] = g.range, w = hi - lo;
      if (a === "left") zoomTo(g, lo - w / 2, hi - w / 2);
      if (a === "right") zoomTo(g, lo + w / 2, hi + w / 2);
      if (a === "out") zoomTo(g, lo - w / 2, hi + w / 2);
      if (a === "all") zoomTo(g, g.full[0], g.full[1]);
    });
    plots.appendChild(nav);
    for (const c of set.channels) {
      // A gap (masked rows, a dropout) breaks the lines: a null row where a step exceeds 5 times the median.
      const steps = c.t.slice(1).map((v, i) => v - c.t[i]).sort((a, b) => a - b), gapAt = set.no_gaps ? Infinity : 5 * (steps[steps.length >> 1] || Infinity);
      const withGaps = s => { const o = []; for (let i = 0; i < c.t.length; i++) { if (i > 0 && c.t[i] - c.t[i - 1] > gapAt) o.push(null); o.push(s[i]); } return o; };
      const tg = []; for (let i = 0; i < c.t.length; i++) { if (i > 0 && c.t[i] - c.t[i - 1] > gapAt) tg.push(0.5 * (c.t[i] + c.t[i - 1])); tg.push(c.t[i]); }
      const yg = withGaps(c.y), unit = units[c.unit] || c.unit, M = c.models, last = M[M.length - 1];
      const head = document.createElement("p"); head.className = "figs";
      head.textContent = c.channel + ": " + M.map(m => (M.length > 1 ? m.label + " " : "") + (m.fit != null ? "fit " + (+m.fit).toFixed(1) + " %, " : "") + "RMS " + fmt(m.rms) + " " + unit +
                         (m.coverage != null ? ", band holds " + (100 * m.coverage).toFixed(1) + " %" : "")).join("; ") + (c.baseline_fit != null && isFinite(c.baseline_fit) ? " (FIR baseline fit " + (+c.baseline_fit).toFixed(1) + " %)" : "");
      plots.appendChild(head);
      const e1 = document.createElement("div"); plots.appendChild(e1);
      const ser = [], arr = [tg];
      M.forEach((m, k) => { ser.push({ label: M.length > 1 ? m.label : "predicted", stroke: palette[k % palette.length], width: 1.5, value: (u, v) => fmt(v) }); arr.push(withGaps(m.p)); });
      ser.push({ label: "95 % low", stroke: "rgba(31,119,180,0.3)", value: (u, v) => fmt(v) }, { label: "95 % high", stroke: "rgba(31,119,180,0.3)", value: (u, v) => fmt(v) });
      arr.push(withGaps(last.lo), withGaps(last.hi));
      // Measured: a line, or (the lab's repetitions) points only.
      const P = (c.points || []).map(q => ({ label: q.label, v: withGaps(q.v) }));
      const dot = (label, color) => ({ label, stroke: color, fill: color, paths: () => null, points: { show: true, size: 6, stroke: color, fill: color }, value: (u, v) => fmt(v) });
      if (c.y && c.y.some(v => v !== null)) { ser.push({ label: "measured", stroke: "#222", width: 1, value: (u, v) => fmt(v) }); arr.push(yg); }
      P.forEach((q, k) => { ser.push(dot(q.label, ["#222", "#c03020", "#7f7f7f", "#bcbd22"][k % 4])); arr.push(q.v); });
      const hiIdx = M.length + 2, loIdx = M.length + 1;
      chart(g, e1, c.channel, unit, ser, arr, c.windows, 240, [{ series: [hiIdx, loIdx], fill: "rgba(31,119,180,0.15)" }]);
      const e2 = document.createElement("div"); plots.appendChild(e2);
      const rser = [], rarr = [tg];
      M.forEach((m, k) => { const pg = withGaps(m.p), col = palette[k % palette.length], who = M.length > 1 ? m.label + " " : "";
                            if (!P.length) { rser.push({ label: who + "residual", stroke: col, width: 1, value: (u, v) => fmt(v) });
                                             rarr.push(yg.map((v, i) => v === null ? null : v - pg[i])); }
                            P.forEach(q => { rser.push(dot(who + q.label, col)); rarr.push(q.v.map((v, i) => v === null ? null : v - pg[i])); }); });
      chart(g, e2, c.channel + " residual (measured − predicted)", unit, rser, rarr, c.windows, 190);
      const sp = document.createElement("div"); sp.innerHTML = bandsTable(c); plots.appendChild(sp);
      if (c.discrepancy) { const dv = document.createElement("div"); dv.innerHTML = discrepancySection(c); plots.appendChild(dv); }
      const fr = document.createElement("div"); fr.innerHTML = frfTable(c); plots.appendChild(fr);
    }
    if (set.view) zoomTo(g, set.view[0], set.view[1]);
    if (D.no_windows) return;
    // The listed windows of every channel, largest share of its residual first; above them, each
    // channel's windows in words (how many there were, what the listed ones hold).
    const rows = [];
    for (const c of set.channels) for (const w of c.windows) rows.push(Object.assign({ channel: c.channel }, w));
    rows.sort((a, b) => (b.share - a.share) || (a.t0 - b.t0));
    for (const c of set.channels) if (c.windows_note) {
      const p = document.createElement("p"); p.className = "note windows-note";
      p.innerHTML = "<b>" + esc(c.channel) + "</b>: " + esc(c.windows_note);
      side.appendChild(p);
    }
    const tbl = document.createElement("table"); tbl.className = "windows";
    tbl.innerHTML = "<caption>" + (D.windows_of ? "where " + D.windows_of + " fails" : "failing windows") + " (" + rows.length + ", largest share first): a row zooms to it</caption><tr><th>channel</th><th>time [s]</th><th>peak |z|</th><th>share</th><th>where</th></tr>";
    for (const w of rows) {
      const tr = document.createElement("tr");
      for (const v of [w.channel, w.t1 > w.t0 ? w.t0.toFixed(3) + "–" + w.t1.toFixed(3) : w.t0.toFixed(3), w.z.toFixed(1), (100 * w.share).toFixed(1) + " %", w.label]) { const td = document.createElement("td"); td.textContent = v; tr.appendChild(td); }
      tr.addEventListener("click", () => { const pad = Math.max(0.5, 2 * (w.t1 - w.t0)); zoomTo(g, w.t0 - pad, w.t1 + pad); });
      tbl.appendChild(tr);
    }
    side.appendChild(tbl);
  });
}
build();
const painted = performance.now();
if (location.hash === "#selftest") {
  const out = { charts: groups.reduce((n, g) => n + g.charts.length, 0), window_rows: document.querySelectorAll("table.windows tr").length - document.querySelectorAll("table.windows").length,
                window_shares: Array.from(document.querySelectorAll("table.windows tr")).filter(r => r.querySelector("td")).map(r => parseFloat(r.children[3].textContent)),
                windows_notes: Array.from(document.querySelectorAll("p.windows-note")).map(p => p.textContent),
                discrepancy: Array.from(document.querySelectorAll("div.discrepancy")).map(d => ({ charts: d.querySelectorAll("svg.discrepancy-chart").length, fits: Array.from(d.querySelectorAll("table.fits td.num")).map(td => td.textContent) })),
                frf_charts: document.querySelectorAll("svg.frf-chart").length,
                ready_ms: Math.round(painted), zoom_ok: false, errors,
                series: groups.length ? groups[0].charts.map(c => c.u.series.length) : [] };
  if (groups.length && groups[0].charts.length) {
    const g = groups[0], lo = g.full[0] + 0.45 * (g.full[1] - g.full[0]), hi = g.full[0] + 0.55 * (g.full[1] - g.full[0]);
    const z0 = performance.now();
    zoomTo(g, lo, hi);
    // uPlot applies a scale change in a microtask: read the scales after it.
    queueMicrotask(() => {
      out.zoom_ms = Math.round(performance.now() - z0);
      out.zoom_ok = g.charts.every(c => Math.abs(c.u.scales.x.min - lo) < 1e-9 * (1 + Math.abs(lo)) && Math.abs(c.u.scales.x.max - hi) < 1e-9 * (1 + Math.abs(hi)));
      out.errors = errors;
      document.getElementById("selftest").textContent = JSON.stringify(out);
    });
  } else {
    document.getElementById("selftest").textContent = JSON.stringify(out);
  }
}
)js";

constexpr const char* kStyle = R"css(
body { font-family: sans-serif; margin: 1em 2em; color: #222; }
h1 { font-size: 1.3em; } h2 { font-size: 1.1em; margin-top: 1.5em; }
.layout { display: flex; gap: 1.5em; align-items: flex-start; }
.plots { flex: 3; min-width: 0; } .side { flex: 1.3; position: sticky; top: 0.5em; max-height: 95vh; overflow: auto; }
.figs { margin: 1em 0 0.2em; font-weight: bold; } .note, .hint { color: #666; font-size: 0.9em; }
.nav button { margin-right: 0.3em; } .hint { margin-left: 1em; }
table { border-collapse: collapse; font-size: 0.85em; } td, th { padding: 2px 6px; border-bottom: 1px solid #ddd; text-align: left; }
table.windows tr:hover { background: #fde2e2; cursor: pointer; } caption { text-align: left; font-weight: bold; padding: 4px 0; }
.spectrum { display: flex; flex-wrap: wrap; align-items: center; gap: 0.5em 1em; margin: 0.6em 0 1em; }
.spectrum svg { max-width: 100%; height: auto; font-family: sans-serif; }
table.bands td.num { text-align: right; } tr.fail td { color: #b00; }
.discrepancy { border-top: 1px solid #ddd; margin: 0.5em 0 1.5em; } .discrepancy h3 { font-size: 1em; margin: 0.6em 0 0.3em; }
table.fits td.num { text-align: right; } .reading { max-width: 60em; }
)css";

}  // namespace

std::string comparePage(const nlohmann::json& compare, const std::string& title) {
  return comparePage(std::vector<PageModel>{PageModel{"model", compare}}, title);
}

std::string comparePage(const std::vector<PageModel>& models, const std::string& title) {
  nlohmann::json data{{"title", title}, {"sets", nlohmann::json::array()}};
  if (models.size() > 1) data["windows_of"] = models.front().label;
  std::map<std::string, std::size_t> set_index;
  std::map<std::string, std::pair<std::size_t, std::size_t>>
      channel_at;  // data set@scenario#channel -> (set, channel)
  const auto keyOf = [](const nlohmann::json& s) {
    return s.value("data_set", "") + "@" + s.value("scenario", "");
  };
  if (!models.empty())
    for (const auto& s : models.front().comparison.value("series", nlohmann::json::array())) {
      if (!s.contains("t")) continue;
      const std::string key = keyOf(s);
      if (!set_index.count(key)) {
        set_index[key] = data["sets"].size();
        data["sets"].push_back(
            {{"name", std::filesystem::path(s.value("data_set", "")).filename().string()},
             {"scenario", s.value("scenario", "")},
             {"channels", nlohmann::json::array()}});
      }
      auto& channels = data["sets"][set_index[key]]["channels"];
      channel_at[key + "#" + s.value("channel", "")] = {set_index[key], channels.size()};
      channels.push_back(slimSeries(s));
    }
  for (const auto& m : models)
    for (const auto& s : m.comparison.value("series", nlohmann::json::array())) {
      const auto at = channel_at.find(keyOf(s) + "#" + s.value("channel", ""));
      if (at == channel_at.end() || !s.contains("predicted_mean") ||
          s.at("predicted_mean").size() != s.at("t").size())
        continue;
      data["sets"][at->second.first]["channels"][at->second.second]["models"].push_back(
          {{"label", m.label},
           {"p", s.at("predicted_mean")},
           {"lo", s.at("band_lo")},
           {"hi", s.at("band_hi")},
           {"fit", s.value("fit_percent", nlohmann::json())},
           {"rms", s.value("rms", nlohmann::json())},
           {"coverage", s.value("coverage95", nlohmann::json())}});
    }
  if (data["sets"].empty())
    throw InputError("compare page", "the comparison holds no series data to draw");
  return timeSeriesPage(
      data,
      "Measured (black), the prediction (blue; with several models one colour each, the last with "
      "its 95 % "
      "band), and the residual under each; the failing windows that hold the most of the residual "
      "shaded red. Lines are drawn as the min and max of "
      "each pixel column of what is in view; the figures and tables are the comparison's own.");
}

std::string timeSeriesPage(const nlohmann::json& data, const std::string& note) {
  const std::string title = data.value("title", std::string("twin"));
  std::string html = "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>" +
                     report::htmlEscape(title) + "</title>\n<style>";
  html += assets::kUplotCss;
  html += kStyle;
  html += "</style></head><body>\n<h1>" + report::htmlEscape(title) + "</h1>\n";
  html += "<p class=note>" + report::htmlEscape(note) +
          "</p>\n<div id=sets></div>\n<pre id=selftest></pre>\n";
  html += "<script type=\"application/json\" id=data>" + scriptSafe(data.dump()) +
          "</script>\n<script>";
  html += assets::kUplotJs;
  html += "</script>\n<script>";
  html += kScript;
  html += "</script>\n</body></html>\n";
  return html;
}

std::string diagnosisPage(const diag::DiagnosisResult& r, const std::string& what,
                          const std::vector<std::string>& data) {
  std::vector<PageModel> models{{"base", r.base.comparison.toJson(true)}};
  const auto plus = [](const std::vector<std::string>& effects) {
    std::string s;
    for (const auto& e : effects) s += " + " + e;
    return s;
  };
  if (r.steps.size() > 1)
    for (std::size_t k = 1; k < r.steps.size(); ++k)
      models.push_back({plus(r.steps[k].effects), r.steps[k].comparison.toJson(true)});
  else
    for (std::size_t k = 1; k < r.causes.size(); ++k)
      models.push_back({plus(r.causes[k].fit.effects), r.causes[k].fit.comparison.toJson(true)});
  std::string title = "twin diagnose: " + what + " against";
  for (const auto& d : data) title += " " + std::filesystem::path(d).filename().string();
  return comparePage(models, title);
}

}  // namespace dtwin
