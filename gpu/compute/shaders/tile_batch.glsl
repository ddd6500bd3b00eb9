// The compositing passes' batch walk over a slot's list (docs/gpu.md "The compute tile
// rasterizer"), shared by the tile rasterizers of voxels and of Gaussians: one work group a slot,
// the list loaded kTilePixels entries at a time into shared memory (one entry an invocation),
// and a batch started only while some pixel of the group is still open (the reference's
// __syncthreads_count early stop). A pass writes its loop as
//   for (uint base = range.x; base < range.y; base += kTilePixels) {
//     tile_batch_vote(done);                                  // this pixel still open?
//     if (base + local < range.y) { ... load entry base + local into the shared batch ... }
//     if (!tile_batch_any_open()) break;                       // the same for the whole group
//     ... composite min(kTilePixels, range.y - base) entries ...
//   }
// Both calls hold barriers: call them in uniform control flow (the loop bounds are the group's).

shared uint tile_batch_open;

// Waits until the last batch is read, then records whether this invocation's pixel is open.
void tile_batch_vote(bool done) {
  barrier();  // the last batch is read, tile_batch_open too
  if (gl_LocalInvocationIndex == 0u) tile_batch_open = 0u;
  barrier();
  if (!done) tile_batch_open = 1u;
}

// Waits until the batch is loaded and every vote is in; false when no pixel of the group is open.
bool tile_batch_any_open() {
  barrier();
  return tile_batch_open != 0u;
}
