// CNCjs's toolpath interpreter on one file: count the moves and the bounds, as a viewer would.
// Usage: node toolpath.js FILE   -> prints "moves N bounds xmin xmax ymin ymax zmin zmax"
const fs = require('fs');
const Toolpath = require('gcode-toolpath').default || require('gcode-toolpath');

const lo = [Infinity, Infinity, Infinity];
const hi = [-Infinity, -Infinity, -Infinity];
let moves = 0;
function extend(p) {
  const v = [p.x, p.y, p.z];
  for (let i = 0; i < 3; i++) {
    if (v[i] < lo[i]) lo[i] = v[i];
    if (v[i] > hi[i]) hi[i] = v[i];
  }
}
const toolpath = new Toolpath({
  addLine: (modal, v1, v2) => { moves += 1; extend(v1); extend(v2); },
  addArcCurve: (modal, v1, v2, v0) => { moves += 1; extend(v1); extend(v2); },
});
toolpath.loadFromStringSync(fs.readFileSync(process.argv[2], 'utf8'));
console.log(`moves ${moves} bounds ${lo[0]} ${hi[0]} ${lo[1]} ${hi[1]} ${lo[2]} ${hi[2]}`);
