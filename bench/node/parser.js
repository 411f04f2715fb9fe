// CNCjs's G-code parser on one file (parseFileSync): parse only, no toolpath.
// Usage: node parser.js FILE   -> prints "lines N"
const { parseFileSync } = require('gcode-parser');
const results = parseFileSync(process.argv[2]);
console.log(`lines ${results.length}`);
