// Distance against image radius: one curve per direction of a fit and the points as dots, plotted
// by uPlot (npm, installed by scripts/setup; the service serves it at /web/vendor/uplot/).

const COLOURS = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b',
                 '#e377c2', '#7f7f7f', '#bcbd22', '#17becf', '#393b79', '#637939'];

let library = null;  // uPlot, imported on first use

function directionColour(thetaDeg, directions) {
  const k = Math.round(((thetaDeg % 360) + 360) % 360 / (360 / directions)) % directions;
  return COLOURS[k % COLOURS.length];
}

/// uPlot's aligned data: the curves' radii and the points' in one sorted x column, each curve and
/// the points a column with null where they have no value.
function plotData(curves, dots) {
  const xs = [...new Set([...curves.flatMap((c) => c.radius_px), ...dots.map((d) => d.radius_px)])]
    .sort((a, b) => a - b);
  const at = new Map(xs.map((x, i) => [x, i]));
  const column = (pairs) => {
    const y = new Array(xs.length).fill(null);
    for (const [x, value] of pairs) y[at.get(x)] = value;
    return y;
  };
  return [xs, ...curves.map((c) => column(c.radius_px.map((r, i) => [r, c.distance_cm[i]]))),
          column(dots.map((d) => [d.radius_px, d.distance_cm]))];
}

/// Plots into `element` (replacing its plot) and returns the uPlot; curves: [{theta_deg,
/// radius_px: [], distance_cm: []}], dots: [{radius_px, distance_cm}]. Throws when the library
/// cannot be loaded.
export async function drawRadialPlot(element, curves, dots) {
  if (!library) {
    library = import('/web/vendor/uplot/uPlot.esm.js').then((m) => m.default).catch(() => {
      library = null;
      throw new Error('the plot library (npm uplot) is not installed: run scripts/setup');
    });
  }
  const UPlot = await library;
  const series = [
    { label: 'radius px' },
    ...curves.map((c) => ({ label: `${c.theta_deg}°`, stroke: directionColour(c.theta_deg, curves.length),
                            width: 1.5, spanGaps: true, points: { show: false } })),
    { label: 'points', stroke: '#1d2420', paths: () => null, points: { show: true, size: 4, fill: '#1d2420' } },
  ];
  element.replaceChildren();
  return new UPlot({
    width: Math.max(280, element.clientWidth), height: 260, series, legend: { show: false },
    scales: { x: { time: false } },
    axes: [{ label: 'radius px' }, { label: 'distance cm' }],
  }, plotData(curves, dots), element);
}
