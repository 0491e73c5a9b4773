// The omni calibration page (docs/web-pages.md): the omnivision paper's Figures 5-7 done in the
// browser, every step through the service's API (/api/v1/omni/...).

import { ImageView } from './image_view.js';
import { $, ApiError, api, circle as circleOn, download, makeGuarded, pageShortcut,
         showError, zoomKey, zoomOnWheel } from './page_support.js';
import { onPointerDrag } from './pointer_drag.js';
import { PointHistory } from './point_history.js';
import { drawRadialPlot } from './radial_plot.js';

const canvas = $('view');
const ctx = canvas.getContext('2d');
const view = new ImageView(canvas);
const history = new PointHistory();
const state = {
  frame: null,        // {frame, width, height, rim, source}
  bitmap: null,
  center: null,       // [x, y]
  candidates: [],     // markers found, not yet accepted
  fit: null,          // the last finished fit: {result, points: the list it was fitted to}
  selected: -1,
  heatmap: false,
  plot: null,         // the curves' uPlot
  checked: null,      // a table checked against the points: {table, check}
};
const GRAB_PX = 9;  // canvas pixels

const guarded = makeGuarded('status', () => render());

function layout() {
  return {
    bearing_step_deg: Number($('layout-step-deg').value),
    min_cm: Number($('layout-min-cm').value),
    max_cm: Number($('layout-max-cm').value),
    step_cm: Number($('layout-ring-cm').value),
  };
}

const centerJson = () => ({ x_px: state.center[0], y_px: state.center[1] });

function setCenter(x, y) {
  state.center = [x, y];
  $('center-x').value = x.toFixed(2);
  $('center-y').value = y.toFixed(2);
}

async function openFrame(body, type) {
  const frame = await api('POST', '/api/v1/omni/frames', body, { type });
  const blob = await api('GET', `/api/v1/omni/frames/${frame.frame}`, undefined, { as: 'blob' });
  const bitmap = await createImageBitmap(blob);
  state.frame = frame;
  state.bitmap = bitmap;
  state.candidates = [];
  state.fit = null;
  if (frame.rim) setCenter(frame.rim.x_px, frame.rim.y_px);
  else setCenter(0.5 * (frame.width - 1), 0.5 * (frame.height - 1));
  view.fit(frame.width, frame.height);
  $('frame-info').textContent = `frame ${frame.frame}: ${frame.width} × ${frame.height}, ${frame.source}` +
    (frame.rim ? `; mirror rim at (${frame.rim.x_px.toFixed(1)}, ${frame.rim.y_px.toFixed(1)}), r ${frame.rim.radius_px.toFixed(1)} px`
               : '; no mirror rim in view');
}

async function suggestPlaces(pixels) {
  const body = { center: centerJson(), layout: layout(), points: pixels.map(([x, y]) => ({ x_px: x, y_px: y })),
                 fit: state.fit && state.fit.result.fit };
  return (await api('POST', '/api/v1/omni/places', body)).points;
}

function currentFit() {
  return state.fit && state.fit.points === history.points ? state.fit.result : null;
}

// --- drawing ---------------------------------------------------------------------------------

function heatColour(errorCm) {
  const t = Math.min(1, Math.abs(errorCm) / 5);
  return `rgba(${Math.round(255 * t)}, ${Math.round(200 * (1 - t))}, 40, 0.4)`;
}

function drawHeatmap(fit) {
  const points = history.points;
  const errors = fit.residuals.map((r) => r.distance_error_cm);
  const cell = 12;
  const { min_px, max_px } = fit.valid_radius;
  for (let y = cell / 2; y < state.frame.height; y += cell) {
    for (let x = cell / 2; x < state.frame.width; x += cell) {
      const r = Math.hypot(x - state.center[0], y - state.center[1]);
      if (r < min_px || r > max_px) continue;
      let sum = 0, weights = 0;
      points.forEach((p, i) => {
        if (errors[i] === null) return;
        const w = 1 / (1 + (p.x_px - x) ** 2 + (p.y_px - y) ** 2);
        sum += w * Math.abs(errors[i]);
        weights += w;
      });
      if (!weights) continue;
      ctx.fillStyle = heatColour(sum / weights);
      const [cx, cy] = view.canvasFromImage(x - cell / 2 - 0.5, y - cell / 2 - 0.5);
      ctx.fillRect(cx, cy, cell * view.scale, cell * view.scale);
    }
  }
}

const circle = (x, y, radius, stroke, fill) => circleOn(ctx, view, x, y, radius, stroke, fill);

function render() {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const fit = currentFit();
  if (state.bitmap) view.draw(ctx, state.bitmap);
  if (state.frame && fit && state.heatmap) drawHeatmap(fit);
  if (state.frame && fit) {
    ctx.setLineDash([6, 4]);
    for (const r of [fit.valid_radius.min_px, fit.valid_radius.max_px]) {
      const [cx, cy] = view.canvasFromImage(state.center[0], state.center[1]);
      ctx.beginPath();
      ctx.arc(cx, cy, r * view.scale, 0, 2 * Math.PI);
      ctx.strokeStyle = '#9ecfff';
      ctx.stroke();
    }
    ctx.setLineDash([]);
  }
  for (const c of state.candidates) circle(c.x_px, c.y_px, 5, '#ff4fd8');
  history.points.forEach((point, i) => {
    const p = drag && drag.kind === 'point' && drag.index === i && drag.preview
      ? { x_px: drag.preview[0], y_px: drag.preview[1] } : point;
    const bad = fit && Math.abs(fit.residuals[i].distance_error_cm) > 3 * Math.max(0.5, fit.errors.distance_cm.median);
    circle(p.x_px, p.y_px, i === state.selected ? 5 : 3.5, '#000', i === state.selected ? '#ff9800' : bad ? '#ff3b30' : '#ffe14d');
  });
  if (state.center) {
    const [cx, cy] = view.canvasFromImage(state.center[0], state.center[1]);
    ctx.strokeStyle = '#00e5ff';
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(cx - 10, cy); ctx.lineTo(cx + 10, cy); ctx.moveTo(cx, cy - 10); ctx.lineTo(cx, cy + 10);
    ctx.stroke();
  }
  renderTable(fit);
  $('point-count').textContent = String(history.points.length);
  $('undo').disabled = !history.past.length;
  $('redo').disabled = !history.future.length;
  for (const id of ['export-table', 'export-iris']) $(id).disabled = !fit;
}

function renderTable(fit) {
  const body = $('points').tBodies[0];
  const rows = history.points.map((p, i) => {
    const residual = fit ? fit.residuals[i].distance_error_cm : null;
    return `<tr data-index="${i}" class="${i === state.selected ? 'selected' : ''}"><td>${i + 1}</td>` +
      `<td>${p.x_px.toFixed(2)}</td><td>${p.y_px.toFixed(2)}</td>` +
      `<td><input data-field="distance_cm" type="number" step="1" value="${Number(p.distance_cm.toFixed(4))}"></td>` +
      `<td><input data-field="bearing_deg" type="number" step="1" value="${p.bearing_deg ?? ''}"></td>` +
      `<td>${residual === null ? '–' : residual.toFixed(2)}</td></tr>`;
  });
  body.innerHTML = rows.join('');
}

function showFit(result) {
  const e = result.errors.distance_cm;
  $('fit-info').textContent = `${result.method} on ${result.samples} points: distance error median ` +
    `${e.median.toFixed(2)} cm, p95 ${e.p95.toFixed(2)} cm, max ${e.max.toFixed(2)} cm; valid radius ` +
    `${result.valid_radius.min_px.toFixed(1)}–${result.valid_radius.max_px.toFixed(1)} px`;
  const dots = history.points.map((p) => {
    const dx = p.x_px - result.center.x_px, dy = result.center.y_px - p.y_px;
    return { radius_px: Math.hypot(dx, dy), distance_cm: p.distance_cm,
             theta_deg: (Math.atan2(dy, dx) * 180 / Math.PI + 360) % 360 };
  });
  drawRadialPlot($('curves'), result.curves, dots)
    .then((plot) => { state.plot = plot; showError('curves-error', null); })
    .catch((e) => showError('curves-error', e));
}

// --- actions ---------------------------------------------------------------------------------

async function runFit() {
  if (!state.frame) throw new ApiError('open a frame first');
  const points = history.points;
  const body = { method: $('method').value, center: centerJson(),
                 image: { width: state.frame.width, height: state.frame.height }, points };
  let fit = await api('POST', '/api/v1/omni/fits', body);
  while (fit.state === 'running') {
    await new Promise((resolve) => setTimeout(resolve, 250));
    fit = await api('GET', `/api/v1/omni/fits/${fit.fit}`);
  }
  if (fit.state === 'failed') throw new ApiError(fit.error);
  state.fit = { result: fit, points };
  showFit(fit);
}

async function exportCsv() {
  const text = await api('POST', '/api/v1/omni/samples', { center: centerJson(), points: history.points }, { as: 'text' });
  download(new Blob([text], { type: 'text/csv' }), 'samples.csv');
}

async function exportTable(format) {
  const fit = currentFit();
  if (!fit) throw new ApiError('fit the current points first');
  const blob = await api('GET', `/api/v1/omni/fits/${fit.fit}/table?format=${format}`, undefined, { as: 'blob' });
  download(blob, format === 'iris' ? 'lut_px2cm.bin' : `omni-${fit.method}.bsmap`);
}

async function importCsv(file) {
  if (!state.center) throw new ApiError('open a frame first: the samples are around its centre');
  const text = await file.text();
  const center = `${state.center[0]},${state.center[1]}`;
  const { points } = await api('POST', `/api/v1/omni/points?center=${encodeURIComponent(center)}`, text, { type: 'text/csv' });
  history.set(points);
}

async function checkTable(file) {
  if (!state.frame) throw new ApiError('open a frame first: a table is checked against its points');
  const bytes = await file.arrayBuffer();
  const table = await api('POST', `/api/v1/omni/frames/${state.frame.frame}/table`, bytes,
                          { type: 'application/octet-stream' });
  const check = await api('POST', `/api/v1/omni/tables/${table.table}/residuals`, { points: history.points });
  state.checked = { table, check };
  const e = check.distance_cm;
  $('table-info').textContent = `${file.name} (${table.method}, ${table.width} × ${table.height}) on ` +
    `${e.count} points: distance error median ${e.median.toFixed(2)} cm, p95 ${e.p95.toFixed(2)} cm, ` +
    `max ${e.max.toFixed(2)} cm; ${check.out_of_range} outside its valid range`;
}

async function addPointAt(x, y) {
  const near = state.candidates.findIndex((c) => Math.hypot(c.x_px - x, c.y_px - y) * view.scale <= GRAB_PX);
  if (near >= 0) {
    const [c] = state.candidates.splice(near, 1);
    history.add(c);
    return;
  }
  const places = await suggestPlaces([...history.points.map((p) => [p.x_px, p.y_px]), [x, y]]);
  const place = places[places.length - 1];
  history.add({ x_px: x, y_px: y, distance_cm: place.distance_cm, bearing_deg: place.bearing_deg });
  state.selected = history.points.length - 1;
}

// --- pointer and keys ------------------------------------------------------------------------

let drag = null;  // while the pointer is down: {kind: 'point'|'center'|'pan', index, preview}

function pointAtCanvas(cx, cy) {
  let best = -1, bestD = GRAB_PX;
  history.points.forEach((p, i) => {
    const [px, py] = view.canvasFromImage(p.x_px, p.y_px);
    const d = Math.hypot(px - cx, py - cy);
    if (d <= bestD) { best = i; bestD = d; }
  });
  return best;
}

onPointerDrag(canvas, view, {
  begin(cx, cy) {
    if (!state.frame) return null;
    canvas.focus();
    const index = pointAtCanvas(cx, cy);
    const [ccx, ccy] = view.canvasFromImage(state.center[0], state.center[1]);
    const kind = index >= 0 ? 'point' : Math.hypot(ccx - cx, ccy - cy) <= GRAB_PX + 3 ? 'center' : 'pan';
    drag = { kind, index, preview: null };
    if (index >= 0) state.selected = index;
    render();
    return drag;
  },
  move(d, cx, cy, dx, dy) {
    const [x, y] = view.imageFromCanvas(cx, cy);
    if (d.kind === 'pan') view.panBy(dx, dy);
    if (d.kind === 'center') setCenter(x, y);
    if (d.kind === 'point') d.preview = [x, y];  // one change, recorded on release
    render();
  },
  end(d, cx, cy, moved) {
    drag = null;
    if (d.kind === 'point' && d.preview) {
      history.update(d.index, { x_px: d.preview[0], y_px: d.preview[1] });
    } else if (d.kind === 'pan' && !moved) {
      const [x, y] = view.imageFromCanvas(cx, cy);
      guarded('markers-error', () => addPointAt(x, y));
      return;
    }
    render();
  },
});

zoomOnWheel(view, render);

document.addEventListener('keydown', (event) => {
  const shortcut = pageShortcut(event);
  if (!shortcut) return;
  const { key, step } = shortcut;
  if (step) history[step]();
  else if ((key === 'delete' || key === 'backspace') && state.selected >= 0) deleteSelected();
  else if (zoomKey(view, key)) { /* zoomed */ }
  else if (key === 'a') acceptAll();
  else if (key === 'h') { state.heatmap = !state.heatmap; $('heatmap').checked = state.heatmap; }
  else return;
  event.preventDefault();
  render();
});

function deleteSelected() {
  if (state.selected < 0 || state.selected >= history.points.length) return;
  history.remove(state.selected);
  state.selected = -1;
}

function acceptAll() {
  if (!state.candidates.length) return;
  history.set([...history.points, ...state.candidates]);
  state.candidates = [];
}

// --- controls --------------------------------------------------------------------------------

$('upload').addEventListener('change', () => {
  const file = $('upload').files[0];
  if (file) guarded('upload-error', () => openFrame(file, file.type || 'application/octet-stream'));
});
$('open-file').addEventListener('click', () => guarded('upload-error', () => openFrame({ file: $('server-files').value })));
$('open-sim').addEventListener('click', () => guarded('upload-error', () => openFrame({ simulated: true })));
$('use-rim').addEventListener('click', () => {
  if (state.frame && state.frame.rim) setCenter(state.frame.rim.x_px, state.frame.rim.y_px);
  render();
});
for (const id of ['center-x', 'center-y']) {
  $(id).addEventListener('change', () => {
    if (state.center) setCenter(Number($('center-x').value), Number($('center-y').value));
    render();
  });
}
$('find-markers').addEventListener('click', () => guarded('markers-error', async () => {
  if (!state.frame) throw new ApiError('open a frame first');
  const found = await api('POST', `/api/v1/omni/frames/${state.frame.frame}/markers`, { center: centerJson(), layout: layout() });
  state.candidates = found.markers;
  $('markers-info').textContent = `${found.markers.length} of ${found.layout_markers} layout markers found ` +
    `(${found.blobs} marker-coloured blobs): click one to accept it, or accept all (A)`;
}));
$('accept-all').addEventListener('click', () => { acceptAll(); render(); });
$('reject-all').addEventListener('click', () => { state.candidates = []; render(); });
$('undo').addEventListener('click', () => { history.undo(); render(); });
$('redo').addEventListener('click', () => { history.redo(); render(); });
$('delete-point').addEventListener('click', () => { deleteSelected(); render(); });
$('suggest').addEventListener('click', () => guarded('markers-error', async () => {
  const places = await suggestPlaces(history.points.map((p) => [p.x_px, p.y_px]));
  history.set(places);
}));
$('fit').addEventListener('click', () => guarded('fit-error', runFit));
$('heatmap').addEventListener('change', () => { state.heatmap = $('heatmap').checked; render(); });
$('export-table').addEventListener('click', () => guarded('fit-error', () => exportTable('ballsight')));
$('export-iris').addEventListener('click', () => guarded('fit-error', () => exportTable('iris')));
$('export-csv').addEventListener('click', () => guarded('import-error', exportCsv));
$('import-csv').addEventListener('change', () => {
  const file = $('import-csv').files[0];
  if (file) guarded('import-error', () => importCsv(file));
});
$('check-table').addEventListener('change', () => {
  const file = $('check-table').files[0];
  if (file) guarded('table-error', () => checkTable(file));
});
$('points').addEventListener('change', (event) => {
  const input = event.target;
  const row = input.closest('tr');
  if (!row || !input.dataset.field) return;
  const value = input.value === '' ? null : Number(input.value);
  history.update(Number(row.dataset.index), { [input.dataset.field]: value });
  render();
});
$('points').addEventListener('click', (event) => {
  const row = event.target.closest('tr[data-index]');
  if (row) { state.selected = Number(row.dataset.index); render(); }
});

async function start() {
  const { files, simulated } = await api('GET', '/api/v1/omni/files');
  $('server-files').innerHTML = files.map((f) => `<option>${f.replace(/</g, '&lt;')}</option>`).join('');
  $('server-files').hidden = !files.length;
  $('open-file').hidden = !files.length;
  $('open-sim').disabled = !simulated;
  render();
}

// For tests and the browser's console.
window.ballsightOmni = {
  view, state, history,
  points: () => history.points.map((p) => ({ ...p })),
  ready: guarded('upload-error', start),
};
