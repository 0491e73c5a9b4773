// The closed loop of `ballsight demo`'s report as a replay: the court map (court_map.js) with a
// time slider and a play button. At time t it shows the robot where it truly was, the balls not
// yet collected, and the route the service had published by then. The data is the report's own
// (eval/loop_replay_data.hpp); the page works from its folder, with no server.
import { drawCourtMap } from "./court_map.js";

/** The index of the last item of `items` (each [time, ...], in time order) at or before `t`. */
function lastAtOrBefore(items, t) {
  let lo = 0;
  let hi = items.length; // items[hi - 1] is the answer once lo == hi
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (items[mid][0] <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo - 1;
}

/** The court at time `t` of `run`, as a navigation update for drawCourtMap. */
export function loopStateAt(run, t) {
  const [, x_m, y_m, heading_deg] = run.path[Math.max(0, lastAtOrBefore(run.path, t))];
  const route = lastAtOrBefore(run.routes, t);
  return {
    world: {
      sites: [],
      balls: run.balls
        .filter(([, , collected]) => collected === null || collected > t)
        .map(([x, y]) => ({ x_m: x, y_m: y })),
      robot: { x_m, y_m, heading_deg },
    },
    route: { waypoints_m: route >= 0 ? run.routes[route][1] : [] },
    given_up: [],
  };
}

const PLAY_SPEED = 10; // simulated seconds per second of playing

/**
 * Wires the replay in `root` (a <select>, a play <button>, an <input type="range">, an <output>
 * and a <canvas>) to `runs` on `site`'s court. The robot's shown position is kept in
 * root.dataset.robot ("x,y" in metres).
 */
export function startLoopReplay(root, site, runs) {
  const canvas = root.querySelector("canvas");
  const slider = root.querySelector("input[type=range]");
  const play = root.querySelector("button");
  const clock = root.querySelector("output");
  const picker = root.querySelector("select");
  let run = runs[0];
  let time = 0; // seconds into the run shown (the slider rounds to its step; playing does not)
  let playing = null; // the animation frame's id while playing

  const show = () => {
    const state = loopStateAt(run, time);
    drawCourtMap(canvas, site, state);
    const { x_m, y_m } = state.world.robot;
    root.dataset.robot = `${x_m},${y_m}`;
    clock.value = `${time.toFixed(1)} s of ${run.duration_s.toFixed(1)} s: ${state.world.balls.length} of ${run.balls.length} balls left`;
  };
  const stop = () => {
    if (playing !== null) cancelAnimationFrame(playing);
    playing = null;
    play.textContent = "Play";
  };
  const select = (index) => {
    stop();
    run = runs[index];
    slider.max = String(run.duration_s);
    time = 0;
    slider.value = "0";
    show();
  };

  runs.forEach((r, k) => picker.add(new Option(r.name, String(k))));
  picker.addEventListener("change", () => select(Number(picker.value)));
  slider.step = "any";
  slider.addEventListener("input", () => {
    stop();
    time = Number(slider.value);
    show();
  });
  play.addEventListener("click", () => {
    if (playing !== null) return stop();
    if (time >= run.duration_s) time = 0;
    play.textContent = "Pause";
    let last = performance.now();
    const step = (now) => {
      time = Math.min(run.duration_s, time + ((now - last) / 1000) * PLAY_SPEED);
      last = now;
      slider.value = String(time);
      show();
      if (time >= run.duration_s) return stop();
      playing = requestAnimationFrame(step);
    };
    playing = requestAnimationFrame(step);
  });
  select(0);
}
