// Writes a .ksplat with mkkellogg/GaussianSplats3D's own generator: the steps of its
// util/create-ksplat.js (v0.4.7), importing the npm build instead of the repository's.
// node create-ksplat.mjs IN.ply OUT.ksplat LEVEL ALPHA_THRESHOLD CENTER BLOCK BUCKET SH_DEGREE
import * as GaussianSplats3D from '@mkkellogg/gaussian-splats-3d';
import * as THREE from 'three';
import * as fs from 'fs';

const [inFile, outFile, level, alpha, center, block, bucket, shDegree] = process.argv.slice(2);
const data = fs.readFileSync(inFile);
const bytes = data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
const splats = GaussianSplats3D.PlyParser.parseToUncompressedSplatArray(bytes, parseInt(shDegree));
const generator = GaussianSplats3D.SplatBufferGenerator.getStandardGenerator(
    parseInt(alpha), parseInt(level), 0, new THREE.Vector3().fromArray(center.split(',').map(parseFloat)),
    parseFloat(block), parseInt(bucket));
const splatBuffer = generator.generateFromUncompressedSplatArray(splats);
fs.writeFileSync(outFile, Buffer.from(splatBuffer.bufferData));
