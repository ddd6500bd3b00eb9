// Writes the test quilts into a folder: a_qs4x3a0.75.png and b_qs4x3a0.75.png (docs/serve.md).
'use strict';
const fs = require('fs');
const path = require('path');
const {quiltPng} = require('./quilt_png.js');
const dir = process.argv[2];
fs.writeFileSync(path.join(dir, 'a_qs4x3a0.75.png'), quiltPng(4, 3, 192, 256));
fs.writeFileSync(path.join(dir, 'b_qs4x3a0.75.png'), quiltPng(4, 3, 96, 128));
