// Draws the court from above on a canvas: the fenced area, the lines (ITF layout), the net, the
// balls, collection sites, the robot, its route and the balls it gave up on. Field frame (docs/conventions.md): origin at
// the court's centre on the net line, x along its length, y across, metres; the canvas shows +y up.

const SINGLES_WIDTH_M = 8.23; // ITF rule 1: the lines a site's court does not list
const SERVICE_LINE_M = 6.4;
const ROBOT_LENGTH_M = 0.6;
const ROBOT_WIDTH_M = 0.45;

/** The field -> canvas transform that fits `site`'s fenced area into `canvas` with a margin. */
export function courtTransform(site, canvas, margin = 16) {
  const c = site.court;
  const scale = Math.min(
    (canvas.width - 2 * margin) / c.area_length_m,
    (canvas.height - 2 * margin) / c.area_width_m,
  );
  const cx = canvas.width / 2;
  const cy = canvas.height / 2;
  return {
    scale,
    toCanvas: (x, y) => [cx + x * scale, cy - y * scale],
    toField: (px, py) => [(px - cx) / scale, (cy - py) / scale],
  };
}

function line(ctx, t, x0, y0, x1, y1) {
  ctx.beginPath();
  ctx.moveTo(...t.toCanvas(x0, y0));
  ctx.lineTo(...t.toCanvas(x1, y1));
  ctx.stroke();
}

function drawCourt(ctx, site, t) {
  const c = site.court;
  const [ax, ay] = t.toCanvas(-c.area_length_m / 2, c.area_width_m / 2);
  ctx.fillStyle = "#2f5a4e";
  ctx.fillRect(ax, ay, c.area_length_m * t.scale, c.area_width_m * t.scale);
  const [bx, by] = t.toCanvas(-c.length_m / 2, c.width_m / 2);
  ctx.fillStyle = "#3f7a55";
  ctx.fillRect(bx, by, c.length_m * t.scale, c.width_m * t.scale);
  ctx.strokeStyle = "#f3f5f2";
  ctx.lineWidth = Math.max(1, 0.05 * t.scale);
  ctx.strokeRect(bx, by, c.length_m * t.scale, c.width_m * t.scale);
  const half = c.length_m / 2;
  const singles = Math.min(SINGLES_WIDTH_M, c.width_m) / 2;
  line(ctx, t, -half, singles, half, singles);
  line(ctx, t, -half, -singles, half, -singles);
  for (const x of [-SERVICE_LINE_M, SERVICE_LINE_M]) line(ctx, t, x, -singles, x, singles);
  line(ctx, t, -SERVICE_LINE_M, 0, SERVICE_LINE_M, 0);
  if (c.net) {
    const post = c.width_m / 2 + c.net_posts_outside_m;
    ctx.strokeStyle = "#111";
    ctx.lineWidth = Math.max(2, 0.08 * t.scale);
    line(ctx, t, 0, -post, 0, post);
  }
}

function disc(ctx, t, x, y, radiusPx, fill, stroke) {
  const [px, py] = t.toCanvas(x, y);
  ctx.beginPath();
  ctx.arc(px, py, radiusPx, 0, 2 * Math.PI);
  if (fill) {
    ctx.fillStyle = fill;
    ctx.fill();
  }
  if (stroke) {
    ctx.strokeStyle = stroke;
    ctx.stroke();
  }
}

function drawRobot(ctx, t, robot) {
  const [px, py] = t.toCanvas(robot.x_m, robot.y_m);
  const heading = (-robot.heading_deg * Math.PI) / 180; // the canvas's y points down
  ctx.save();
  ctx.translate(px, py);
  ctx.rotate(heading);
  ctx.fillStyle = "#8a8f8c";
  ctx.strokeStyle = "#1d2420";
  ctx.lineWidth = 1.5;
  const l = ROBOT_LENGTH_M * t.scale;
  const w = ROBOT_WIDTH_M * t.scale;
  ctx.fillRect(-l / 2, -w / 2, l, w);
  ctx.strokeRect(-l / 2, -w / 2, l, w);
  ctx.beginPath();
  ctx.moveTo(0, 0);
  ctx.lineTo(l, 0);
  ctx.lineTo(0.8 * l, -0.15 * l);
  ctx.moveTo(l, 0);
  ctx.lineTo(0.8 * l, 0.15 * l);
  ctx.stroke();
  ctx.restore();
}

function drawRoute(ctx, t, route) {
  const points = route?.waypoints_m ?? [];
  if (points.length < 2) return;
  ctx.strokeStyle = "#2f6fd6";
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(...t.toCanvas(points[0][0], points[0][1]));
  for (const [x, y] of points.slice(1)) ctx.lineTo(...t.toCanvas(x, y));
  ctx.stroke();
}

/** A red cross over each ball the robot gave up on. */
function drawGivenUp(ctx, t, marks, halfPx) {
  ctx.strokeStyle = "#d0342c";
  ctx.lineWidth = 2;
  for (const m of marks) {
    const [x, y] = t.toCanvas(m.x_m, m.y_m);
    ctx.beginPath();
    ctx.moveTo(x - halfPx, y - halfPx);
    ctx.lineTo(x + halfPx, y + halfPx);
    ctx.moveTo(x + halfPx, y - halfPx);
    ctx.lineTo(x - halfPx, y + halfPx);
    ctx.stroke();
  }
}

/** The whole picture of one navigation update (`update` may be null: the court alone). */
export function drawCourtMap(canvas, site, update) {
  const ctx = canvas.getContext("2d");
  const t = courtTransform(site, canvas);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  drawCourt(ctx, site, t);
  if (!update) return t;
  drawRoute(ctx, t, update.route);
  ctx.lineWidth = 1.5;
  for (const s of update.world.sites)
    disc(ctx, t, s.x_m, s.y_m, Math.max(4, (s.diameter_m / 2) * t.scale), null, "#7fe07f");
  const ballPx = Math.max(3, site.ball_radius_m * t.scale);
  for (const b of update.world.balls) disc(ctx, t, b.x_m, b.y_m, ballPx, "#e4f53c", "#3a4a10");
  drawGivenUp(ctx, t, update.given_up ?? [], ballPx + 3);
  if (update.world.robot) drawRobot(ctx, t, update.world.robot);
  return t;
}

/** A line plot of `values` (latest last) filling `canvas`, scaled to their largest. */
export function drawSparkline(canvas, values, colour = "#24402f") {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (values.length < 2) return;
  const top = Math.max(...values, 1e-9);
  ctx.strokeStyle = colour;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  values.forEach((v, i) => {
    const x = (i / (values.length - 1)) * (canvas.width - 4) + 2;
    const y = canvas.height - 14 - (v / top) * (canvas.height - 20);
    if (i === 0) ctx.moveTo(x, y);
    else ctx.lineTo(x, y);
  });
  ctx.stroke();
  ctx.fillStyle = "#4a554f";
  ctx.font = "11px system-ui, sans-serif";
  ctx.fillText(`max ${top.toFixed(1)} ms`, 4, canvas.height - 2);
}
