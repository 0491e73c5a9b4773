// The live dashboard (/): the court from above with the latest navigation update of the service's
// stream (/api/v1/stream, docs/robot-link.md), and the service's health. What is drawn is also in
// window.ballsightDashboard ({seq, balls, robot, route}), for tests and the browser's console.
import { drawCourtMap, drawSparkline } from "/web/court_map.js";

const LATENCY_POINTS = 60;
const RECONNECT_MS = [250, 500, 1000, 2000, 4000];

const $ = (id) => document.getElementById(id);
const state = { site: null, update: null, latencies: [], serviceId: "", seq: 0, retries: 0 };
window.ballsightDashboard = { seq: 0, balls: [], robot: null, route: null };

function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
}

function fixed(value, digits) {
  return typeof value === "number" && Number.isFinite(value) ? value.toFixed(digits) : "-";
}

function showUpdate(update) {
  drawCourtMap($("court"), state.site, update);
  const { world, route } = update;
  $("seq").textContent = String(update.seq);
  $("balls").textContent = String(world.balls.length);
  $("robot").textContent = world.robot
    ? `${fixed(world.robot.x_m, 2)}, ${fixed(world.robot.y_m, 2)} m, ${fixed(world.robot.heading_deg, 0)} deg`
    : "not seen";
  $("route").textContent = `${route.order.length} balls, ${fixed(route.length_m, 1)} m, ${fixed(route.time_s, 0)} s (${route.planner})`;
  window.ballsightDashboard = { seq: update.seq, balls: world.balls, robot: world.robot, route };
  state.latencies.push((update.published_ns - update.capture_time_ns) / 1e6);
  state.latencies.splice(0, Math.max(0, state.latencies.length - LATENCY_POINTS));
  drawSparkline($("latency"), state.latencies);
}

function showHealth(health) {
  $("frame-sets").textContent = String(health.frame_sets ?? "-");
  $("rate").textContent = `${fixed(health.frame_sets_per_s, 1)} /s`;
  $("pipeline").textContent = `${fixed(health.pipeline_ms, 1)} ms, plan ${fixed(health.plan_ms, 1)} ms`;
  $("collected").textContent = health.sim ? `${health.sim.collected} (${health.sim.balls_left} left)` : "-";
  const list = $("cameras");
  list.replaceChildren(
    ...(health.cameras ?? []).map((camera) => {
      const item = document.createElement("li");
      item.textContent = `${camera.name}: ${camera.state}`;
      if (camera.state !== "ok" && camera.state !== "simulated") item.className = "failed";
      return item;
    }),
  );
}

function connect() {
  const query = new URLSearchParams({ topics: "navigation,health", after: String(state.seq) });
  if (state.serviceId) query.set("service", state.serviceId);
  const socket = new WebSocket(`ws://${location.host}/api/v1/stream?${query}`);
  socket.onopen = () => {
    state.retries = 0;
    $("connection").textContent = "live";
    showError("");
  };
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.topic === "navigation") {
      state.seq = message.update.seq;
      state.serviceId = message.update.service_id;
      showUpdate(message.update);
    } else if (message.topic === "health") {
      showHealth(message.health);
    }
  };
  socket.onclose = () => {
    const wait = RECONNECT_MS[Math.min(state.retries++, RECONNECT_MS.length - 1)];
    $("connection").textContent = `reconnecting in ${wait} ms`;
    setTimeout(connect, wait);
  };
}

async function start() {
  try {
    const response = await fetch("/api/v1/site");
    if (!response.ok) throw new Error(`/api/v1/site: ${response.status} ${await response.text()}`);
    state.site = await response.json();
  } catch (error) {
    showError(`cannot read the site: ${error.message}`);
    $("connection").textContent = "offline";
    return;
  }
  drawCourtMap($("court"), state.site, null);
  connect();
}

start();
