#include "device/context.h"

#include <cstdlib>
#include <limits>

#include "device/kernel_cache.h"
#include "device/kernel_sources.h"
#include "device/runtime_env.h"
#include "stats/process_clock.h"
#include "util/input_limits.h"
#include "util/log.h"

namespace gdr {
namespace {

// $GDR_KERNELS: scene (the default) or all.
bool scene_kernels_by_default() {
  const char* env = std::getenv("GDR_KERNELS");
  const std::string mode = env ? env : "";
  if (mode.empty() || mode == "scene") return true;
  if (mode == "all") return false;
  throw Error("GDR_KERNELS=" + mode + ": expected scene (build only the code the scene uses) or all (every type)");
}

}  // namespace

Context::Context(const DeviceInfo& device, Stats* stats)
    : device_(device), stats_(stats), scene_kernels_(scene_kernels_by_default()) {
  zero_copy_ = is_cpu() || device_.host_unified;
  configure_runtime(0);
  cl_int err = CL_SUCCESS;
  cl_context_properties props[] = {CL_CONTEXT_PLATFORM,
                                   reinterpret_cast<cl_context_properties>(device.platform), 0};
  context_ = clCreateContext(props, 1, &device_.device, nullptr, nullptr, &err);
  cl_check(err, "clCreateContext");
  for (cl_command_queue& q : queues_) {
    q = clCreateCommandQueue(context_, device_.device, CL_QUEUE_PROFILING_ENABLE, &err);
    if (err == CL_SUCCESS) continue;
    for (cl_command_queue made : queues_) {
      if (made) clReleaseCommandQueue(made);
    }
    clReleaseContext(context_);
    cl_check(err, "clCreateCommandQueue");
  }
  if (stats_) {
    stats_->set("device/name", device_.name);
    stats_->set("device/platform", device_.platform_name);
    stats_->set("device/type", device_.type);
  }
  set_scene_kernels(scene_kernels_);
}

void Context::set_scene_kernels(bool on) {
  scene_kernels_ = on;
  if (stats_) stats_->set("device/kernels", on ? "scene" : "all");
}

Context::~Context() {
  try {
    finish();
  } catch (...) {  // a failed kernel: nothing left to report it to
  }
  kept_.clear();
  programs_.clear();
  for (cl_command_queue q : queues_) {
    if (q) clReleaseCommandQueue(q);
  }
  if (context_) clReleaseContext(context_);
}

void Context::finish() const {
  cl_int err = CL_SUCCESS;
  for (cl_command_queue q : queues_) {
    cl_int e = clFinish(q);
    if (err == CL_SUCCESS) err = e;
  }
  collect_timings();
  cl_check(err, "clFinish");
}

void Context::collect_timings() const {
  std::vector<Pending> pending;
  pending.swap(pending_);
  cl_int first_error = CL_SUCCESS;
  std::string failed;
  for (const Pending& p : pending) {
    cl_int err = clWaitForEvents(1, &p.event);
    if (err == CL_SUCCESS && stats_) {
      cl_ulong start = 0, end = 0;
      clGetEventProfilingInfo(p.event, CL_PROFILING_COMMAND_START, sizeof(start), &start, nullptr);
      clGetEventProfilingInfo(p.event, CL_PROFILING_COMMAND_END, sizeof(end), &end, nullptr);
      stats_->add_time("kernel/" + p.name, end > start ? (end - start) * 1e-9 : 0.0);
      stats_->add_count("kernel_items/" + p.name, p.items);
    }
    if (err != CL_SUCCESS && first_error == CL_SUCCESS) {
      first_error = err;
      failed = p.name;
    }
    clReleaseEvent(p.event);
  }
  if (first_error != CL_SUCCESS) cl_check(first_error, ("running kernel " + failed).c_str());
}

std::string program_build_options(const Defines& defines) {
  std::string options = "-cl-std=CL1.2";
  for (const auto& [name, value] : defines) {
    options += " -D" + name;
    if (!value.empty()) options += "=" + value;
  }
  return options;
}

std::shared_ptr<Program> Context::program(const std::string& root, const Defines& defines) {
  std::string options = program_build_options(defines);
  std::string key = root + "|" + options;
  if (auto it = programs_.find(key); it != programs_.end()) return it->second;

  ScopedTimer timer(stats_, "kernel_build/" + root);
  std::string source = resolve_kernel_source(root);
  KernelCache cache(device_, options, source);
  cl_int err = CL_SUCCESS;
  cl_program program = nullptr;
  std::vector<unsigned char> binary = cache.load();
  if (!binary.empty()) {
    const unsigned char* bin = binary.data();
    size_t size = binary.size();
    cl_int status = CL_SUCCESS;
    program = clCreateProgramWithBinary(context_, 1, &device_.device, &size, &bin, &status, &err);
    if (err != CL_SUCCESS || status != CL_SUCCESS ||
        clBuildProgram(program, 1, &device_.device, options.c_str(), nullptr, nullptr) != CL_SUCCESS) {
      if (program) clReleaseProgram(program);
      program = nullptr;  // a stale or foreign binary: build from source below
    } else if (stats_) {
      stats_->add_count("kernel_cache/hits");
    }
  }
  if (!program) {
    const char* text = source.c_str();
    size_t length = source.size();
    program = clCreateProgramWithSource(context_, 1, &text, &length, &err);
    cl_check(err, "clCreateProgramWithSource");
    err = clBuildProgram(program, 1, &device_.device, options.c_str(), nullptr, nullptr);
    size_t log_size = 0;
    clGetProgramBuildInfo(program, device_.device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &log_size);
    std::string build_log(log_size, '\0');
    if (log_size) {
      clGetProgramBuildInfo(program, device_.device, CL_PROGRAM_BUILD_LOG, log_size, build_log.data(), nullptr);
      build_log.resize(build_log.find('\0') == std::string::npos ? log_size : build_log.find('\0'));
    }
    if (err != CL_SUCCESS) {
      clReleaseProgram(program);
      throw DeviceError("building kernels/" + root + " (" + options + ") on " + device_.name +
                        " failed:\n" + name_resolved_lines(build_log, source));
    }
    if (log::level() >= log::Level::Verbose && build_log.find("warning") != std::string::npos) {
      log::verbose("kernels/", root, ": ", name_resolved_lines(build_log, source));  // mapped only when shown
    }
    if (stats_) stats_->add_count("kernel_cache/misses");
    cache.store(program);
  }
  log::verbose("built kernels/", root, " (", options, ") in ", timer.elapsed(), " s");
  auto result = std::make_shared<Program>(*this, program);
  programs_[key] = result;
  return result;
}

Program::~Program() {
  if (program_) clReleaseProgram(program_);
}

Kernel Program::kernel(const std::string& name) const {
  cl_int err = CL_SUCCESS;
  cl_kernel k = clCreateKernel(program_, name.c_str(), &err);
  cl_check(err, ("clCreateKernel(" + name + ")").c_str());
  return Kernel(*context_, k, name);
}

Kernel::Kernel(Context& context, cl_kernel kernel, std::string name)
    : context_(&context), kernel_(kernel), name_(std::move(name)) {}

Kernel::~Kernel() {
  if (kernel_) clReleaseKernel(kernel_);
}

Kernel::Kernel(Kernel&& o) noexcept : context_(o.context_), kernel_(o.kernel_), name_(std::move(o.name_)) {
  o.kernel_ = nullptr;
}

void Kernel::run(size_t global, size_t local) { run_lanes(global, 1, local); }

void Kernel::run_lanes(size_t items, size_t lanes, size_t local) {
  if (items == 0) return;
  size_t groups = (items + lanes - 1) / lanes;
  size_t padded = (groups + local - 1) / local * local;
  launch(1, &padded, &local, items);
}

void Kernel::run_2d(size_t width, size_t height, size_t local_x, size_t local_y) {
  if (width == 0 || height == 0) return;
  size_t global[2] = {(width + local_x - 1) / local_x * local_x, (height + local_y - 1) / local_y * local_y};
  size_t local[2] = {local_x, local_y};
  launch(2, global, local, width * height);
}

void Kernel::launch(cl_uint dims, const size_t* global, const size_t* local, size_t items) {
  if (!context_->launched_) {
    context_->launched_ = true;
    // From process start to here: runtime set-up, scene load, BVH and kernel builds.
    if (context_->stats()) context_->stats()->set("startup/first_kernel_launch_seconds", seconds_since_process_start());
  }
  if (context_->deferred_) {
    // Without stats no event is needed at all.
    cl_event event = nullptr;
    cl_event* want = context_->stats() ? &event : nullptr;
    cl_check(clEnqueueNDRangeKernel(context_->queue(), kernel_, dims, nullptr, global, local, 0, nullptr, want),
             ("launching kernel " + name_).c_str());
    if (event) context_->pending_.push_back(Context::Pending{event, name_, items});
    if (context_->pending_.size() >= 1024) context_->collect_timings();
    return;
  }
  cl_event event = nullptr;
  cl_check(clEnqueueNDRangeKernel(context_->queue(), kernel_, dims, nullptr, global, local, 0, nullptr, &event),
           ("launching kernel " + name_).c_str());
  cl_int err = clWaitForEvents(1, &event);
  if (err == CL_SUCCESS && context_->stats()) {
    cl_ulong start = 0, end = 0;
    clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_START, sizeof(start), &start, nullptr);
    clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_END, sizeof(end), &end, nullptr);
    context_->stats()->add_time("kernel/" + name_, end > start ? (end - start) * 1e-9 : 0.0);
    context_->stats()->add_count("kernel_items/" + name_, items);
  }
  clReleaseEvent(event);
  cl_check(err, ("running kernel " + name_).c_str());
}


void check_buffer_size(const Context& context, size_t count, size_t element_size) {
  const DeviceInfo& d = context.device();
  if (count > std::numeric_limits<size_t>::max() / element_size) {
    throw DeviceError("a device buffer of " + std::to_string(count) + " elements of " + std::to_string(element_size) +
                      " bytes is larger than any memory");
  }
  size_t bytes = count * element_size;
  if (d.max_alloc > 0 && bytes > d.max_alloc) {
    throw DeviceError("a device buffer of " + format_bytes(bytes) + " (" + std::to_string(bytes) +
                      " bytes) is more than " + d.name + " allows in one allocation: " + format_bytes(d.max_alloc) +
                      " (CL_DEVICE_MAX_MEM_ALLOC_SIZE; device memory " + format_bytes(d.global_memory) +
                      "); render a smaller image");
  }
}

void throw_buffer_error(const Context& context, size_t bytes, cl_int err) {
  const DeviceInfo& d = context.device();
  throw DeviceError("clCreateBuffer failed: " + std::string(cl_error_name(err)) + " for a buffer of " +
                    format_bytes(bytes) + " (" + std::to_string(bytes) + " bytes; " + d.name +
                    " allows " + format_bytes(d.max_alloc) + " in one allocation, device memory " +
                    format_bytes(d.global_memory) + ")");
}

}  // namespace gdr
