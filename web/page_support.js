// What the pages share: requests to the service's API with its errors as messages, its
// WebSocket's URL, errors shown beside the control that caused them, downloads, and zoom by
// wheel and keys.

export const $ = (id) => document.getElementById(id);

export class ApiError extends Error {}

/// A request to the API; its JSON (or text, or blob) answer, or an ApiError "where: error".
export async function api(method, path, body, { as = 'json', type, token } = {}) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.body = typeof body === 'string' || body instanceof Blob || body instanceof ArrayBuffer
      ? body : JSON.stringify(body);
    init.headers['Content-Type'] = type || 'application/json';
  }
  if (token) init.headers.Authorization = `Bearer ${token}`;
  const response = await fetch(path, init);
  if (!response.ok) {
    let message = `HTTP ${response.status}`;
    try {
      const e = await response.json();
      message = `${e.where}: ${e.error}`;
    } catch { /* not JSON */ }
    throw new ApiError(message);
  }
  if (as === 'blob') return response.blob();
  if (as === 'text') return response.text();
  return response.json();
}

/// The URL of the service's WebSocket at `path` (with its query) on this page's own host: wss
/// when the page came over https, ws otherwise.
export function socketUrl(path) {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}${path}`;
}

/// Shows `error` (an Error or a message) in the element `id`; hides it for none.
export function showError(id, error) {
  const el = $(id);
  el.textContent = error ? String(error.message || error) : '';
  el.hidden = !error;
}

/// `guarded(errorId, work)` runs `work`, showing its error beside `errorId` and "working…" in
/// the element `statusId` while any work runs, then calls `render`.
export function makeGuarded(statusId, render) {
  let busy = 0;
  return async (errorId, work) => {
    showError(errorId, null);
    busy += 1;
    $(statusId).textContent = 'working…';
    try {
      await work();
    } catch (e) {
      showError(errorId, e);
    } finally {
      busy -= 1;
      if (!busy) $(statusId).textContent = '';
      render();
    }
  };
}

export function download(blob, name) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/// 'undo' for Ctrl+Z, 'redo' for Ctrl+Y or Ctrl+Shift+Z, else null.
function historyKey(event) {
  if (!(event.ctrlKey || event.metaKey)) return null;
  const key = event.key.toLowerCase();
  if (key === 'z') return event.shiftKey ? 'redo' : 'undo';
  return key === 'y' ? 'redo' : null;
}

/// What a key event asks of a calibration page: {step: 'undo' | 'redo'}, or {key} (lower case)
/// for a plain key, or null when the event is the browser's or a field's (typing into an input,
/// other Ctrl/Alt combinations).
export function pageShortcut(event) {
  const typing = event.target instanceof HTMLSelectElement ||
    (event.target instanceof HTMLInputElement && !['file', 'checkbox', 'button'].includes(event.target.type));
  if (typing) return null;
  const step = historyKey(event);
  if (step) return { step };
  if (event.ctrlKey || event.metaKey || event.altKey) return null;
  return { key: event.key.toLowerCase() };
}

/// The wheel zooms `view` about the cursor, then `render`.
export function zoomOnWheel(view, render) {
  view.canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const [cx, cy] = view.canvasFromClient(event.clientX, event.clientY);
    view.zoomAt(cx, cy, Math.exp(-event.deltaY * 0.0015));
    render();
  }, { passive: false });
}

/// '+' and '-' zoom about the canvas's centre, '0' shows the image whole; whether `key` was one.
export function zoomKey(view, key) {
  const { width, height } = view.canvas;
  if (key === '+' || key === '=') view.zoomAt(width / 2, height / 2, 1.25);
  else if (key === '-') view.zoomAt(width / 2, height / 2, 0.8);
  else if (key === '0' && view.width) view.fit(view.width, view.height);
  else return false;
  return true;
}

/// A circle of `radius` canvas pixels about image point (x, y).
export function circle(ctx, view, x, y, radius, stroke, fill, width = 1.5) {
  const [cx, cy] = view.canvasFromImage(x, y);
  ctx.beginPath();
  ctx.arc(cx, cy, radius, 0, 2 * Math.PI);
  if (fill) { ctx.fillStyle = fill; ctx.fill(); }
  if (stroke) { ctx.strokeStyle = stroke; ctx.lineWidth = width; ctx.stroke(); }
}
