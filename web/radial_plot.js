// Distance against image radius: one curve per direction of a fit, the points as dots, drawn on
// a canvas with axes (no library).

const COLOURS = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b',
                 '#e377c2', '#7f7f7f', '#bcbd22', '#17becf', '#393b79', '#637939'];

export function directionColour(thetaDeg, directions) {
  const k = Math.round(((thetaDeg % 360) + 360) % 360 / (360 / directions)) % directions;
  return COLOURS[k % COLOURS.length];
}

/// curves: [{theta_deg, radius_px: [], distance_cm: []}]; dots: [{radius_px, distance_cm, theta_deg}].
export function drawRadialPlot(canvas, curves, dots) {
  const ctx = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height, left = 46, bottom = 30, top = 10, right = 10;
  ctx.clearRect(0, 0, w, h);
  const xs = [], ys = [];
  for (const c of curves) {
    c.radius_px.forEach((r, i) => { if (c.distance_cm[i] !== null) { xs.push(r); ys.push(c.distance_cm[i]); } });
  }
  for (const d of dots) { xs.push(d.radius_px); ys.push(d.distance_cm); }
  if (!xs.length) return;
  const xMax = Math.max(...xs) * 1.05, yMax = Math.max(...ys) * 1.05;
  const px = (r) => left + (w - left - right) * r / xMax;
  const py = (d) => h - bottom - (h - top - bottom) * d / yMax;
  ctx.strokeStyle = '#4a554f';
  ctx.fillStyle = '#4a554f';
  ctx.font = '11px system-ui, sans-serif';
  ctx.beginPath();
  ctx.moveTo(left, top); ctx.lineTo(left, h - bottom); ctx.lineTo(w - right, h - bottom);
  ctx.stroke();
  for (let i = 0; i <= 4; ++i) {
    const r = xMax * i / 4, d = yMax * i / 4;
    ctx.fillText(r.toFixed(0), px(r) - 8, h - bottom + 14);
    ctx.fillText(d.toFixed(0), 4, py(d) + 4);
  }
  ctx.fillText('radius px', w - right - 52, h - 4);
  ctx.save(); ctx.translate(12, top + 60); ctx.rotate(-Math.PI / 2); ctx.fillText('distance cm', 0, 0); ctx.restore();
  for (const c of curves) {
    ctx.strokeStyle = directionColour(c.theta_deg, curves.length);
    ctx.beginPath();
    let drawing = false;
    c.radius_px.forEach((r, i) => {
      const d = c.distance_cm[i];
      if (d === null) { drawing = false; return; }
      if (drawing) ctx.lineTo(px(r), py(d)); else ctx.moveTo(px(r), py(d));
      drawing = true;
    });
    ctx.stroke();
  }
  for (const d of dots) {
    ctx.fillStyle = directionColour(d.theta_deg, curves.length || 12);
    ctx.fillRect(px(d.radius_px) - 1.5, py(d.distance_cm) - 1.5, 3, 3);
  }
}
