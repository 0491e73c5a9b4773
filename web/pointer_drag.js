// A canvas's pointer as both calibration pages use it: press, then either a click (released
// within 3 canvas pixels of where it was pressed) or a drag (moved further). Coordinates are the
// canvas's (view.canvasFromClient).
const CLICK_SLOP_PX = 3;

/// Calls `begin(cx, cy)` on a press (it returns the drag's own state, or null to ignore the
/// press), `move(drag, cx, cy, dx, dy)` for every movement once it is a drag (dx, dy since the
/// last one), and `end(drag, cx, cy, moved)` on release.
export function onPointerDrag(canvas, view, { begin, move, end }) {
  let drag = null;
  canvas.addEventListener('pointerdown', (event) => {
    const [cx, cy] = view.canvasFromClient(event.clientX, event.clientY);
    const own = begin(cx, cy);
    if (own === null) return;
    drag = { own, start: [cx, cy], last: [cx, cy], moved: false };
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const [cx, cy] = view.canvasFromClient(event.clientX, event.clientY);
    if (Math.hypot(cx - drag.start[0], cy - drag.start[1]) > CLICK_SLOP_PX) drag.moved = true;
    if (!drag.moved) return;
    move(drag.own, cx, cy, cx - drag.last[0], cy - drag.last[1]);
    drag.last = [cx, cy];
  });
  canvas.addEventListener('pointerup', (event) => {
    if (!drag) return;
    const { own, moved } = drag;
    drag = null;
    const [cx, cy] = view.canvasFromClient(event.clientX, event.clientY);
    end(own, cx, cy, moved);
  });
}
