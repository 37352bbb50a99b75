#include "fapc/face/preview_page.hpp"

#include <cmath>
#include <cstdio>

#include "fapc/codec/fap_table.hpp"
#include "fapc/codec/xml_escape.hpp"
#include "preview_page_3d.hpp"

namespace fapc::face {

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// The page's script: reads the data block, draws the curves, keeps the cursor on the video's
// time. Written for this page; no library.
constexpr std::string_view kScript = R"JS(
const data = JSON.parse(document.getElementById('fap-data').textContent);
const video = document.getElementById('face');
const plot = document.getElementById('curves');
const scrub = document.getElementById('scrub');
const play = document.getElementById('play');
const clock = document.getElementById('clock');
const table = document.getElementById('values');
const ctx = plot.getContext('2d');
// The 3D view, when the page has one: it draws each frame the cursor shows, and the page says it
// is ready only once its head is loaded.
const head3d = window.fapcHead3d || null;
const whenLoaded = f => (head3d ? head3d.loaded : Promise.resolve()).then(f);
const margin = data.plotMargin, W = plot.width, H = plot.height;
const duration = data.frames / data.rate;
// Each curve is scaled to its own largest |value|, so small FAPs keep their shape beside head
// rotations in the thousands; the table gives the values themselves.
for (const f of data.faps) f.scale = Math.max(1e-9, ...f.values.map(Math.abs));
const lo = -1, hi = 1;
const colours = ['#1f77b4','#d62728','#2ca02c','#9467bd','#ff7f0e','#8c564b','#e377c2','#17becf','#7f7f7f','#bcbd22'];
const xOf = t => margin + (W - 2 * margin) * (duration > 0 ? t / duration : 0);
const yOf = v => H - margin / 2 - (H - margin) * (v - lo) / (hi - lo);
function frameAt(t) { return Math.max(0, Math.min(data.frames - 1, Math.floor(t * data.rate + 1e-6))); }
function drawCurves() {
  ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
  ctx.strokeStyle = '#ccc'; ctx.beginPath(); ctx.moveTo(margin, yOf(0)); ctx.lineTo(W - margin, yOf(0)); ctx.stroke();
  data.faps.forEach((f, i) => {
    ctx.strokeStyle = colours[i % colours.length]; ctx.beginPath();
    f.values.forEach((v, j) => { const x = xOf(j / data.rate), y = yOf(v / f.scale); j ? ctx.lineTo(x, y) : ctx.moveTo(x, y); });
    ctx.stroke();
  });
}
let background = null;
function show(t) {
  const k = frameAt(t), shown = k / data.rate;
  if (!background) { drawCurves(); background = ctx.getImageData(0, 0, W, H); }
  ctx.putImageData(background, 0, 0);
  const x = xOf(shown);
  ctx.strokeStyle = '#000'; ctx.lineWidth = 1; ctx.beginPath(); ctx.moveTo(x + 0.5, 0); ctx.lineTo(x + 0.5, H); ctx.stroke();
  if (head3d) head3d.show(shown);
  clock.textContent = shown.toFixed(2) + ' s  (frame ' + k + ')';
  scrub.value = shown;
  table.innerHTML = data.faps.map((f, i) => '<tr><td style="color:' + colours[i % colours.length] + '">' + f.number + '</td><td>' + f.name + '</td><td>' + f.values[k] + '</td></tr>').join('');
  document.body.dataset.cursorTime = shown;
  document.body.dataset.cursorX = x;
}
function tick() { show(video.currentTime); if (!video.paused) requestAnimationFrame(tick); }
play.onclick = () => { if (video.paused) { video.play(); } else { video.pause(); } };
video.onplay = () => { play.textContent = 'pause'; requestAnimationFrame(tick); };
video.onpause = () => { play.textContent = 'play'; show(video.currentTime); };
scrub.oninput = () => { video.currentTime = parseFloat(scrub.value) + 0.5 / data.rate; show(parseFloat(scrub.value)); };
// 'seeked' comes when the frame is decoded, before it is on screen: the page says it is ready two
// animation frames later, once the browser has painted (a screenshot taken at once showed the old
// frame under load; requestVideoFrameCallback never fires for a paused seek in headless Chromium).
video.addEventListener('seeked', () => whenLoaded(() => {
  show(video.currentTime);
  requestAnimationFrame(() => requestAnimationFrame(() => { document.title = 'ready ' + video.currentTime; }));
}));
const wanted = /#t=([0-9.]+)/.exec(location.hash);
function start() {
  if (wanted) { video.currentTime = parseFloat(wanted[1]); } else { whenLoaded(() => { show(0); document.title = 'ready 0'; }); }
}
// The video may have its first frame before this script runs (the 3D view's scripts come first).
if (video.readyState >= 2) { start(); } else { video.addEventListener('loadeddata', start); }
show(wanted ? parseFloat(wanted[1]) : 0);
)JS";

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string preview_page(const FaceTrack& track, std::string_view webm, const PreviewOptions& o) {
  const int rate = o.frame_rate > 0 ? o.frame_rate : track.fps();
  const std::int64_t frames = std::max<std::int64_t>(
      1, rate == track.fps() ? track.frame_count() : std::llround(track.duration_seconds() * rate));
  // The values of every moving FAP at each picture of the video: what the cursor reads.
  std::string faps;
  for (int fap : track.moving_faps()) {
    if (!faps.empty()) faps += ",\n";
    faps +=
        "{\"number\":" + std::to_string(fap) + ",\"name\":\"" + std::string(find_fap(fap)->name) + "\",\"values\":[";
    for (std::int64_t j = 0; j < frames; ++j) {
      if (j) faps += ',';
      faps += number(std::round(track.at_time(double(j) / rate)[static_cast<std::size_t>(fap - 1)] * 100) / 100);
    }
    faps += "]}";
  }
  const std::string title = xml_escape(o.title.empty() ? "fapc preview" : o.title);
  std::string page;
  page.reserve((webm.size() + o.head_glb.size()) * 4 / 3 + faps.size() + 8192);
  page += "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + title + "</title>\n";
  page +=
      "<meta name=\"generator\" content=\"fapc render\">\n<style>\n"
      "body{margin:0;font:14px sans-serif;background:#f4f5f7}\n"
      "#face{display:" +
      std::string(o.view == PreviewView::three_d ? "none" : "block") +
      ";position:absolute;left:0;top:0}\n#head3d{position:absolute;top:0;left:" + std::to_string(head3d_left(o)) +
      "px}\n"
      "#panel{position:absolute;left:0;top:" +
      std::to_string(o.height) +
      "px;padding:8px}\n"
      "#side{position:absolute;left:" +
      std::to_string(o.width + head3d_left(o) + 8) + "px;top:0;max-height:" + std::to_string(o.height) +
      "px;overflow:auto}\n"
      "#scrub{width:" +
      std::to_string(kPlotWidth - 2 * kPlotMargin) + "px;margin-left:" + std::to_string(kPlotMargin - 8) +
      "px}\ntd{padding:0 6px}\n</style></head>\n<body>\n";
  page += "<video id=\"face\" width=\"" + std::to_string(o.width) + "\" height=\"" + std::to_string(o.height) +
          (o.sound ? "\"" : "\" muted") + " playsinline preload=\"auto\" src=\"data:video/webm;base64,";
  page += base64(webm);
  page += "\"></video>\n";
  if (o.view != PreviewView::two_d) page += head3d_view(o);
  page += "<div id=\"side\"><b>" + title + "</b><table id=\"values\"></table></div>\n";
  page += "<div id=\"panel\"><button id=\"play\">play</button> <span id=\"clock\"></span><br>\n";
  char range[200];
  std::snprintf(range, sizeof range,
                "<input id=\"scrub\" type=\"range\" min=\"0\" max=\"%.6g\" step=\"%.6g\" value=\"0\"><br>\n",
                double(frames - 1) / rate, 1.0 / rate);
  page += range;
  page += "<canvas id=\"curves\" width=\"" + std::to_string(kPlotWidth) + "\" height=\"220\"></canvas></div>\n";
  page += "<script id=\"fap-data\" type=\"application/json\">{\"rate\":" + std::to_string(rate) +
          ",\"frames\":" + std::to_string(frames) + ",\"plotMargin\":" + std::to_string(kPlotMargin) + ",\"faps\":[\n" +
          faps + "]}</script>\n<script>";
  page += kScript;
  page += "</script>\n</body></html>\n";
  return page;
}

}  // namespace fapc::face
