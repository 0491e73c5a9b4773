// The court calibration page (docs/web-pages.md): per camera a still, the reference balls found
// in it and the pose fitted to them, corrected by hand; the calibration file; a ball colour model
// from clicked balls. Every step through the service's API (/api/v1/court-calibration/...).

import { ImageView } from './image_view.js';
import { $, ApiError, api, circle as circleOn, download, makeGuarded, pageShortcut,
         showError, zoomKey, zoomOnWheel } from './page_support.js';
import { onPointerDrag } from './pointer_drag.js';
import { PointHistory } from './point_history.js';

const API = '/api/v1/court-calibration';
const canvas = $('view');
const ctx = canvas.getContext('2d');
const view = new ImageView(canvas);
// The corrections of the still on screen: [{reference, x_px, y_px}] placed, [{reference, absent}].
const history = new PointHistory();
const state = {
  site: null,        // {cameras, references, writes_files}
  camera: null,      // the camera's name
  still: null,       // {still, camera, width, height}
  bitmap: null,
  pose: null,        // the pose answer for `posedFor`
  posedFor: null,    // the corrections list the pose was fitted to
  selected: null,    // a reference ball's name
  colourMode: false,
  clicks: [],        // [x, y] on ball pixels
  colours: null,     // {colours, balls}
  saveInfo: '',      // what the last save wrote
};
let poseRequest = 0;  // the latest pose request's number: older answers are dropped
const GRAB_PX = 10;  // canvas pixels
const guarded = makeGuarded('status', () => render());
const circle = (x, y, radius, stroke, fill, width) => circleOn(ctx, view, x, y, radius, stroke, fill, width);

function corrections() {
  const placed = history.points.filter((c) => !c.absent)
    .map(({ reference, x_px, y_px }) => ({ reference, x_px, y_px }));
  const absent = history.points.filter((c) => c.absent).map((c) => c.reference);
  return { placed, absent };
}

async function fitPose() {
  const forList = history.points;
  const mine = ++poseRequest;
  showError('save-error', null);  // it was about the pose before this one
  state.pose = null;
  state.posedFor = null;
  if (!state.still) return;
  let pose = null;
  try {
    pose = await api('POST', `${API}/stills/${state.still.still}/pose`, corrections());
  } catch (e) {
    if (mine !== poseRequest) return;  // a newer request answers for the page
    state.posedFor = forList;          // the error belongs to these corrections
    throw e;
  }
  if (mine !== poseRequest) return;
  state.pose = pose;
  state.posedFor = forList;
}

/// Sets the corrections (undoable) and fits the pose again.
function correct(list) {
  history.set(list);
  return guarded('pose-error', fitPose);
}

function place(reference, x, y) {
  return correct([...history.points.filter((c) => c.reference !== reference), { reference, x_px: x, y_px: y }]);
}

function toggleAbsent(reference) {
  const was = history.points.find((c) => c.reference === reference && c.absent);
  const others = history.points.filter((c) => c.reference !== reference);
  return correct(was ? others : [...others, { reference, absent: true }]);
}

async function takeStill(camera) {
  const still = await api('POST', `${API}/stills`, { camera });
  const blob = await api('GET', `${API}/stills/${still.still}`, undefined, { as: 'blob' });
  state.bitmap = await createImageBitmap(blob);
  state.still = still;
  state.camera = still.camera;
  state.selected = null;
  state.saveInfo = '';
  state.colours = null;
  state.clicks = [];
  history.past = [];
  history.future = [];
  history.points = [];
  view.fit(still.width, still.height);
  $('still-info').textContent = `still ${still.still} of ${still.camera}: ${still.width} × ${still.height}`;
  await guarded('pose-error', fitPose);
}

// --- drawing ---------------------------------------------------------------------------------

function label(x, y, text, colour) {
  const [cx, cy] = view.canvasFromImage(x, y);
  ctx.font = '12px system-ui, sans-serif';
  ctx.lineWidth = 3;
  ctx.strokeStyle = 'rgba(0, 0, 0, 0.7)';
  ctx.strokeText(text, cx + 9, cy - 7);
  ctx.fillStyle = colour;
  ctx.fillText(text, cx + 9, cy - 7);
}

function cross(x, y, size, colour) {
  const [cx, cy] = view.canvasFromImage(x, y);
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(cx - size, cy - size); ctx.lineTo(cx + size, cy + size);
  ctx.moveTo(cx - size, cy + size); ctx.lineTo(cx + size, cy - size);
  ctx.stroke();
}

const COLOURS = { found: '#38d66b', placed: '#4da3ff', missing: '#ff4d4d', absent: '#9aa39e' };

function drawPose(pose) {
  for (const b of pose.blobs) circle(b.x_px, b.y_px, 2, null, 'rgba(220, 220, 220, 0.8)');
  for (const r of pose.references) {
    const colour = COLOURS[r.state];
    const at = r.seen || r.projected;
    if (!at) continue;
    const selected = r.name === state.selected;
    if (r.state === 'absent') cross(at.x_px, at.y_px, 5, colour);
    else if (r.seen) circle(r.seen.x_px, r.seen.y_px, selected ? 11 : 8, colour, null, selected ? 3 : 2);
    if (r.projected && r.state !== 'absent') {
      ctx.setLineDash(r.seen ? [] : [4, 3]);
      circle(r.projected.x_px, r.projected.y_px, r.seen ? 2.5 : 8, r.seen ? '#fff' : colour, null, 1.5);
      ctx.setLineDash([]);
    }
    label(at.x_px, at.y_px, r.name, selected ? '#ffb74d' : colour);
  }
}

function render() {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (state.bitmap) view.draw(ctx, state.bitmap);
  const pose = state.posedFor === history.points ? state.pose : null;
  if (pose) drawPose(pose);
  for (const [x, y] of state.clicks) cross(x, y, 4, '#ff4fd8');
  if (state.colours) {
    for (const b of state.colours.balls) circle(b.x_px, b.y_px, Math.max(5, b.radius_px * view.scale), '#ffe14d');
  }
  renderCameras();
  renderTable(pose);
  $('undo').disabled = !history.past.length;
  $('redo').disabled = !history.future.length;
  $('save').hidden = !(state.site && state.site.writes_files);
  $('token').hidden = $('save').hidden;
  $('save-info').textContent = state.site && !state.site.writes_files
    ? 'This service has no calibration files (the simulated court): download the file.' : state.saveInfo;
  $('colour-count').textContent = `${state.clicks.length} click${state.clicks.length === 1 ? '' : 's'}`;
  $('colour-mode').checked = state.colourMode;
  canvas.style.cursor = state.colourMode || state.selected ? 'crosshair' : 'grab';
}

function renderCameras() {
  for (const button of $('cameras').querySelectorAll('button')) {
    button.setAttribute('aria-pressed', String(button.dataset.camera === state.camera));
  }
}

const escapeHtml = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/"/g, '&quot;');

function renderTable(pose) {
  if (!state.site) return;
  const byName = new Map((pose ? pose.references : []).map((r) => [r.name, r]));
  const absent = new Set(corrections().absent);
  const rows = state.site.references.map((ref) => {
    const r = byName.get(ref.name);
    const status = r ? r.state : absent.has(ref.name) ? 'absent' : '–';
    const residual = r && r.residual_px !== null ? r.residual_px.toFixed(2) : '–';
    const name = escapeHtml(ref.name);
    return `<tr data-name="${name}" class="${ref.name === state.selected ? 'selected' : ''} ${status === 'absent' ? 'absent' : ''}">` +
      `<td>${name}</td><td class="state-${status}">${status}</td><td>${residual}</td>` +
      `<td><button type="button" data-action="absent">${status === 'absent' ? 'present' : 'absent'}</button></td></tr>`;
  });
  $('references').tBodies[0].innerHTML = rows.join('');
  if (pose) {
    const p = pose.camera_position_m;
    $('matched').textContent = `${pose.matched} of ${pose.references.length}`;
    $('pose-info').textContent = `reprojection rms ${pose.rms_px.toFixed(3)} px, max ${pose.max_px.toFixed(3)} px; ` +
      `camera at (${p.x.toFixed(2)}, ${p.y.toFixed(2)}, ${p.z.toFixed(2)}) m; ${pose.blobs.length} blobs of the reference colour`;
  } else {
    $('matched').textContent = '';
    $('pose-info').textContent = '';
  }
}

// --- pointer and keys ------------------------------------------------------------------------

function referenceAtCanvas(cx, cy) {
  const pose = state.posedFor === history.points ? state.pose : null;
  if (!pose) return null;
  let best = null, bestD = GRAB_PX;
  for (const r of pose.references) {
    const at = r.seen || r.projected;
    if (!at) continue;
    const [px, py] = view.canvasFromImage(at.x_px, at.y_px);
    const d = Math.hypot(px - cx, py - cy);
    if (d <= bestD) { best = r.name; bestD = d; }
  }
  return best;
}

onPointerDrag(canvas, view, {
  begin() {
    if (!state.still) return null;
    canvas.focus();
    return {};
  },
  move(drag, cx, cy, dx, dy) {
    view.panBy(dx, dy);
    render();
  },
  end(drag, cx, cy, moved) {
    if (moved) return;
    const [x, y] = view.imageFromCanvas(cx, cy);
    const inImage = x >= -0.5 && y >= -0.5 && x < state.still.width - 0.5 && y < state.still.height - 0.5;
    if (!inImage) {
      // Outside the image: nothing to place or learn there.
    } else if (state.colourMode) {
      state.clicks.push([x, y]);
    } else if (state.selected) {
      const reference = state.selected;
      state.selected = null;
      place(reference, x, y);
      return;
    } else {
      state.selected = referenceAtCanvas(cx, cy);
    }
    render();
  },
});

zoomOnWheel(view, render);

document.addEventListener('keydown', (event) => {
  const shortcut = pageShortcut(event);
  if (!shortcut) return;
  const { key, step } = shortcut;
  if (step) { if (history[step]()) guarded('pose-error', fitPose); }
  else if ((key === 'delete' || key === 'backspace') && state.selected) {
    correct(history.points.filter((c) => c.reference !== state.selected));
  }
  else if (key === 'x' && state.selected) toggleAbsent(state.selected);
  else if (key === 'escape') state.selected = null;
  else if (key === 'c') state.colourMode = !state.colourMode;
  else if (zoomKey(view, key)) { /* zoomed */ }
  else return;
  event.preventDefault();
  render();
});

// --- controls --------------------------------------------------------------------------------

async function poseFile() {
  if (!state.still) throw new ApiError('take a still first');
  return api('POST', `${API}/stills/${state.still.still}/pose?format=yaml`, corrections(), { as: 'blob' });
}

$('take-still').addEventListener('click', () => guarded('still-error', () => takeStill(state.camera)));
$('cameras').addEventListener('click', (event) => {
  const button = event.target.closest('button[data-camera]');
  if (button) guarded('still-error', () => takeStill(button.dataset.camera));
});
$('references').addEventListener('click', (event) => {
  const row = event.target.closest('tr[data-name]');
  if (!row) return;
  const name = row.dataset.name;
  if (event.target.closest('button[data-action="absent"]')) {
    toggleAbsent(name);
    return;
  }
  state.selected = state.selected === name ? null : name;
  render();
});
$('undo').addEventListener('click', () => { if (history.undo()) guarded('pose-error', fitPose); });
$('redo').addEventListener('click', () => { if (history.redo()) guarded('pose-error', fitPose); });
$('reset').addEventListener('click', () => correct([]));
$('download').addEventListener('click', () => guarded('save-error', async () => {
  download(await poseFile(), `${state.still.camera.replace(/[^\w.-]+/g, '_')}.yml`);
}));
$('save').addEventListener('click', () => guarded('save-error', async () => {
  if (!state.still) throw new ApiError('take a still first');
  const answer = await api('PUT', `${API}/stills/${state.still.still}/calibration`, corrections(),
                           { token: $('token').value });
  state.saveInfo = `wrote ${answer.written} (rms ${answer.rms_px.toFixed(3)} px)` +
    (answer.applied ? '; the service uses it from the next frame set' : '');
}));
$('colour-mode').addEventListener('change', () => { state.colourMode = $('colour-mode').checked; render(); });
$('clear-clicks').addEventListener('click', () => { state.clicks = []; state.colours = null; render(); });
const colourBody = () => ({ clicks: state.clicks.map(([x, y]) => ({ x_px: x, y_px: y })) });
$('learn').addEventListener('click', () => guarded('colour-error', async () => {
  if (!state.still) throw new ApiError('take a still first');
  state.colours = await api('POST', `${API}/stills/${state.still.still}/colours`, colourBody());
  const names = state.colours.colours.colours.map((c) => c.name).join(', ');
  $('colour-info').textContent = `${names}: ${state.colours.balls.length} balls found in this still with it`;
}));
$('download-colours').addEventListener('click', () => guarded('colour-error', async () => {
  if (!state.still) throw new ApiError('take a still first');
  download(await api('POST', `${API}/stills/${state.still.still}/colours?format=file`, colourBody(), { as: 'blob' }),
           'ball-colours.json');
}));

async function start() {
  state.site = await api('GET', `${API}/site`);
  $('cameras').innerHTML = state.site.cameras
    .map((c) => `<button type="button" data-camera="${escapeHtml(c.name)}">${escapeHtml(c.name)}</button>`).join('');
  if (!state.site.cameras.length) return;
  await firstFrameSet();
  await takeStill(state.site.cameras[0].name);
}

/// Waits (10 s at most) until the service has published a frame set: a service just started has
/// no frame to make a still of yet.
async function firstFrameSet() {
  for (let attempt = 0; attempt < 40; attempt += 1) {
    const health = await api('GET', '/api/v1/health');
    if (health.frame_sets > 0) return;
    await new Promise((resolve) => setTimeout(resolve, 250));
  }
}

// For tests and the browser's console.
window.ballsightCourt = {
  view, state, history,
  posed: () => state.posedFor === history.points,
  ready: guarded('still-error', start),
};
