// The overlap test's broadphase, built on the host or on the device (overlap_broadphase.hpp).
#include "overlap_broadphase.hpp"

#include <algorithm>
#include <string>

#include "animpak/reference/overlap.hpp"

namespace animpak::opencl {

namespace {

// Room for list entries before the first total is known: a pair's box meets about 2 x 2 x 2 cells
// (the cell is the mean box's extent), so this is four times that with some to spare.
std::size_t first_capacity(std::int32_t pairs) { return static_cast<std::size_t>(pairs) * 32 + 1024; }

}  // namespace

OverlapBroadphase::OverlapBroadphase(const cl::Context& context, const cl::CommandQueue& queue,
                                     const cl::Program& program, const Topology& topo, const WorldInfo& world,
                                     const ScratchBuffers& scratch, bool on_device)
    : on_device_(on_device), context_(context) {
  // The slice pairs in increasing slice order (hence element order), as reference::build_overlap_grid.
  std::vector<std::int32_t> pair_slice, pair_element;
  for (std::int32_t e = 0; e < topo.element_count(); ++e)
    for (std::int32_t s = topo.element_slice_begin[e]; s + 1 < topo.element_slice_begin[e + 1]; ++s) {
      pair_slice.push_back(s);
      pair_element.push_back(e);
    }
  pairs_ = static_cast<std::int32_t>(pair_slice.size());
  // build_overlap_grid's own bound on the cells: the device grid never has more.
  cell_capacity_ = 8 * pairs_ + 64;
  info_ = make_buffer(context, CL_MEM_READ_WRITE, sizeof(OverlapGridInfo), "overlap_grid_info");
  start_capacity_ = static_cast<std::size_t>(cell_capacity_) + 1;
  start_ = make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * start_capacity_, "overlap_cell_start");
  capacity_ = first_capacity(pairs_);
  elements_ = make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * capacity_, "overlap_elements");
  if (!on_device_) return;

  pair_slice_ = upload_buffer(context, queue, pair_slice, "overlap_pair_slice", CL_MEM_READ_ONLY);
  pair_element_ = upload_buffer(context, queue, pair_element, "overlap_pair_element", CL_MEM_READ_ONLY);
  const std::size_t cells = sizeof(std::int32_t) * static_cast<std::size_t>(cell_capacity_);
  count_ = make_buffer(context, CL_MEM_READ_WRITE, cells, "overlap_cell_count");
  cursor_ = make_buffer(context, CL_MEM_READ_WRITE, cells, "overlap_cell_cursor");
  const std::int32_t blocks = (cell_capacity_ + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  block_sum_ = make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * blocks, "overlap_scan_blocks");
  total_ = upload_buffer(context, queue, std::vector<std::int32_t>{0}, "overlap_total");  // no lists before a build
  // The collision grid's scan kernels (grid.cl) run over the cell capacity: a GridInfo with just that.
  const GridInfo scan{0, 1.0f, pairs_, cell_capacity_, 0, 0, 0};
  extent_ = Kernel(program, "overlap_grid_extent");
  values_ = ArgValues{{"world", world}, {"slice_geometry", scratch.slice_geometry.buffer()}};
  for (const Arg& a : std::initializer_list<Arg>{{"pairs", pairs_},
                                                 {"cell_capacity", cell_capacity_},
                                                 {"pair_slice", pair_slice_},
                                                 {"pair_element", pair_element_},
                                                 {"grid_info", info_},
                                                 {"cell_count", count_},
                                                 {"cell_start", start_},
                                                 {"cursor", cursor_},
                                                 {"total", total_}})
    values_.add(a);
  extent_.bind(values_);
  clear_ = Kernel(program, "grid_clear");
  clear_.bind({{"grid", scan}, {"cell_count", count_}});
  count_kernel_ = Kernel(program, "overlap_grid_count");
  count_kernel_.bind(values_);
  block_sums_ = Kernel(program, "grid_block_sums");
  block_sums_.bind({{"grid", scan}, {"cell_count", count_}, {"block_sum", block_sum_}});
  scan_blocks_ = Kernel(program, "grid_scan_blocks");
  scan_blocks_.bind({{"grid", scan}, {"block_sum", block_sum_}});
  scan_cells_ = Kernel(program, "grid_scan_cells");
  scan_cells_.bind({{"grid", scan},
                    {"start_plane", 0},
                    {"cell_count", count_},
                    {"block_start", block_sum_},
                    {"starts", start_},
                    {"cursor", cursor_}});
  scatter_ = Kernel(program, "overlap_grid_scatter");
  order_ = Kernel(program, "overlap_grid_order");
  bind_lists();
}

void OverlapBroadphase::bind_lists() {
  const cl_int capacity = static_cast<cl_int>(capacity_);
  values_.add({"capacity", capacity});
  values_.add({"elements", elements_});
  scatter_.bind(values_);
  order_.bind(values_);
}

std::array<Launch, 8> OverlapBroadphase::launches() {
  const std::int32_t blocks = (cell_capacity_ + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  return {{{&extent_, AP_LOCAL_SIZE},  // one work-group
           {&clear_, cell_capacity_},
           {&count_kernel_, pairs_},
           {&block_sums_, blocks},
           {&scan_blocks_, AP_LOCAL_SIZE},  // one work-group
           {&scan_cells_, blocks},
           {&scatter_, pairs_},
           {&order_, cell_capacity_}}};
}

void OverlapBroadphase::upload(const cl::CommandQueue& queue, const Topology& topo, const SliceBoxes& boxes) {
  reference::build_overlap_grid(topo, boxes, host_);
  host_info_ = {host_.nx, host_.ny, host_.nt, host_.x0, host_.y0, host_.t0, host_.cell, host_.cell_t};
  check(queue.enqueueWriteBuffer(info_, CL_FALSE, 0, sizeof(OverlapGridInfo), &host_info_),
        "clEnqueueWriteBuffer(overlap_grid_info)");
  const auto put = [&](cl::Buffer& buffer, std::size_t& capacity, const std::vector<std::int32_t>& data,
                       const char* name) {
    if (data.size() > capacity) {
      capacity = data.size() + data.size() / 2;
      buffer = make_buffer(context_, CL_MEM_READ_WRITE, sizeof(std::int32_t) * capacity, name);
    }
    if (!data.empty())
      check(queue.enqueueWriteBuffer(buffer, CL_FALSE, 0, sizeof(std::int32_t) * data.size(), data.data()),
            std::string("clEnqueueWriteBuffer(") + name + ")");
  };
  // build_overlap_grid keeps to 8 cells per pair + 64, the room made for them: the cell ranges never grow.
  put(start_, start_capacity_, host_.cell_start, "overlap_cell_start");
  put(elements_, capacity_, host_.elements, "overlap_elements");
}

void OverlapBroadphase::add_values(ArgValues& values) const {
  values.add({"overlap_grid", info_});
  values.add({"overlap_start", start_});
  values.add({"overlap_elements", elements_});
}

void OverlapBroadphase::bind(Kernel& repulsion) const {
  repulsion.set("overlap_grid", info_);
  repulsion.set("overlap_start", start_);
  repulsion.set("overlap_elements", elements_);
}

void OverlapBroadphase::make_room(std::int32_t total) {
  if (!on_device_ || total < 0) return;
  const std::size_t need = static_cast<std::size_t>(total);
  if (need + need / 3 > capacity_) set_capacity(2 * need);
}

void OverlapBroadphase::set_capacity(std::size_t entries) {
  if (!on_device_) return;
  capacity_ = std::max<std::size_t>(entries, 1);
  elements_ = make_buffer(context_, CL_MEM_READ_WRITE, sizeof(std::int32_t) * capacity_, "overlap_elements");
  bind_lists();
}

OverlapGrid OverlapBroadphase::read(const cl::CommandQueue& queue) const {
  OverlapGridInfo info{};
  check(queue.enqueueReadBuffer(info_, CL_TRUE, 0, sizeof(info), &info), "clEnqueueReadBuffer(overlap_grid_info)");
  OverlapGrid g;
  g.nx = info.nx, g.ny = info.ny, g.nt = info.nt;
  g.x0 = info.x0, g.y0 = info.y0, g.t0 = info.t0, g.cell = info.cell, g.cell_t = info.cell_t;
  g.cell_start.assign(1, 0);
  g.elements.clear();
  if (g.nx == 0) return g;
  const std::size_t cells = static_cast<std::size_t>(g.nx) * g.ny * g.nt;
  g.cell_start.resize(cells + 1);
  check(queue.enqueueReadBuffer(start_, CL_TRUE, 0, sizeof(std::int32_t) * (cells + 1), g.cell_start.data()),
        "clEnqueueReadBuffer(overlap_cell_start)");
  // A device build's lists start at the first cell's start (0); the cells past nx·ny·nt are empty.
  g.elements.resize(static_cast<std::size_t>(g.cell_start.back()));
  if (!g.elements.empty())
    check(queue.enqueueReadBuffer(elements_, CL_TRUE, 0, sizeof(std::int32_t) * g.elements.size(), g.elements.data()),
          "clEnqueueReadBuffer(overlap_elements)");
  return g;
}

}  // namespace animpak::opencl
