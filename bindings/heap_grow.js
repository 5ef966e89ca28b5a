// Linked into the glue (--js-library): growing the wasm memory to an exact size. The glue's
// own growth (emscripten_resize_heap, when malloc runs out) doubles the memory, by 256 MB at
// most (bindings/CMakeLists.txt), so that a call whose need nobody knows beforehand
// (refinement's Steiner points) grows it a few times, not a dozen: in Node each growth can
// cost a collection of the caller's whole JS heap. reserveHeap() knows what a call needs and
// takes exactly that.
mergeInto(LibraryManager.library, {
  geocdt_grow_heap_to__deps: ['$emscripten_realloc_buffer'],
  geocdt_grow_heap_to: function (bytes) {
    return emscripten_realloc_buffer(bytes >>> 0) ? 1 : 0;
  },
});
