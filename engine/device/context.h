// One OpenCL device in use: its context and in-order profiling queues, program builds (with a
// persistent binary cache), kernel launches that record their device time, and typed buffers.
#pragma once
#include <CL/cl.h>

#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "device/cl.h"
#include "device/devices.h"
#include "stats/stats.h"

namespace gdr {

// -D defines for a program build: name -> value ("" for a bare -Dname).
using Defines = std::map<std::string, std::string>;

class Program;

class Context {
 public:
  explicit Context(const DeviceInfo& device, Stats* stats = nullptr);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& device() const { return device_; }
  bool is_cpu() const { return device_.type == "cpu"; }
  cl_context handle() const { return context_; }
  // Commands (launches, reads, maps) go to the current queue: queue 0 unless a QueueScope selects
  // another. Each queue is in order; commands of different queues may run at the same time, so
  // that the host can wait on one batch of paths while the device works on another's.
  static constexpr int kQueues = 2;
  cl_command_queue queue() const { return queues_[current_]; }
  int current_queue() const { return current_; }
  void select_queue(int index) { current_ = index; }
  Stats* stats() const { return stats_; }
  // Whether the host works on ray queues in place (mapped: CPU devices, and devices in the host's
  // memory) or copies them to and from the device around Embree's traversal (a discrete GPU:
  // timed as transfers). Ray queues made after a change follow it.
  bool zero_copy() const { return zero_copy_; }
  void set_zero_copy(bool on) { zero_copy_ = on; }

  // What program builds compile: only the BSDF, light and texture code of the scene at hand
  // (KernelFactory's scene defines; the default), or every type of each, one build of a program
  // that serves every scene. A cold cache then builds each program once, not once per scene;
  // the kernels carry the code of every type. $GDR_KERNELS (scene or all) sets the default.
  bool scene_kernels() const { return scene_kernels_; }
  void set_scene_kernels(bool on);

  // Builds kernels/<root> with `defines`; the same (root, defines) is built once per Context.
  // Throws DeviceError with the compiler log (file:line of the kernel source) on failure.
  std::shared_ptr<Program> program(const std::string& root, const Defines& defines = {});

  // Waits for every queued command of every queue; with deferred timing also records the
  // kernels' times.
  void finish() const;

  // Deferred timing: Kernel::run returns once the launch is queued instead of waiting for its
  // end; device times are read at the next finish() (or after many launches). The in-order queue
  // keeps results the same, and blocking reads still wait for the kernels before them. A kernel
  // failure then shows at finish(). Off by default; DeferredTiming turns it on for a scope.
  void set_deferred_timing(bool on) { deferred_ = on; }
  bool deferred_timing() const { return deferred_; }

  // A slot for an object that a subsystem keeps with this context between calls (device buffers
  // it reuses, so that repeated calls do not allocate and first-touch fresh memory each time).
  // Empty until the caller fills it; released before the context.
  std::shared_ptr<void>& kept(const std::string& key) { return kept_[key]; }

 private:
  DeviceInfo device_;
  Stats* stats_;
  cl_context context_ = nullptr;
  cl_command_queue queues_[kQueues] = {};
  int current_ = 0;
  bool zero_copy_ = false;
  bool scene_kernels_ = true;
  std::map<std::string, std::shared_ptr<Program>> programs_;
  std::map<std::string, std::shared_ptr<void>> kept_;
  friend class Kernel;
  struct Pending {
    cl_event event;
    std::string name;
    size_t items;
  };
  void collect_timings() const;
  bool deferred_ = false;
  bool launched_ = false;  // a kernel has run (start-up time recorded)
  mutable std::vector<Pending> pending_;
};

// Deferred timing for the life of this object; at its end the queue is finished.
class DeferredTiming {
 public:
  explicit DeferredTiming(Context& ctx) : ctx_(ctx), was_(ctx.deferred_timing()) {
    ctx.set_deferred_timing(true);
  }
  ~DeferredTiming() {
    ctx_.set_deferred_timing(was_);
    try {
      ctx_.finish();
    } catch (...) {  // reported by the next call that waits on the queue
    }
  }
  DeferredTiming(const DeferredTiming&) = delete;
  DeferredTiming& operator=(const DeferredTiming&) = delete;

 private:
  Context& ctx_;
  bool was_;
};

// Selects queue `index` for the commands of this scope.
class QueueScope {
 public:
  QueueScope(Context& ctx, int index) : ctx_(ctx), was_(ctx.current_queue()) { ctx.select_queue(index); }
  ~QueueScope() { ctx_.select_queue(was_); }
  QueueScope(const QueueScope&) = delete;
  QueueScope& operator=(const QueueScope&) = delete;

 private:
  Context& ctx_;
  int was_;
};

class Kernel;

class Program {
 public:
  Program(Context& context, cl_program program) : context_(&context), program_(program) {}
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  Kernel kernel(const std::string& name) const;
  cl_program handle() const { return program_; }

 private:
  Context* context_;
  cl_program program_;
};

template <class T>
class Buffer;

class Kernel {
 public:
  Kernel(Context& context, cl_kernel kernel, std::string name);
  ~Kernel();
  Kernel(Kernel&& other) noexcept;
  Kernel& operator=(Kernel&&) = delete;
  Kernel(const Kernel&) = delete;

  template <class T>
  void set_arg(cl_uint index, const Buffer<T>& buffer) {
    cl_mem mem = buffer.handle();
    cl_check(clSetKernelArg(kernel_, index, sizeof(cl_mem), &mem), "clSetKernelArg");
  }
  template <class T>
  void set_arg(cl_uint index, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "kernel arguments are plain data");
    cl_check(clSetKernelArg(kernel_, index, sizeof(T), &value), "clSetKernelArg");
  }
  // Sets all arguments in order. An argument that stands for several kernel parameters (the
  // scene's buffers: DeviceScene) binds them itself through `cl_uint bind_to(Kernel&, cl_uint
  // first) const`, which returns how many it set.
  template <class... Args>
  Kernel& args(const Args&... a) {
    cl_uint i = 0;
    ((i += bind(i, a)), ...);
    return *this;
  }

  // Runs over `global` work items, padded up to a multiple of `local` (PoCL compiles again for
  // every new local size, so it stays fixed; kernels check their own bound). Waits for the end
  // and adds the device time to stats under "kernel/<name>".
  void run(size_t global, size_t local = 64);
  // `items` for a kernel whose work items take `lanes` consecutive items each (the stats count
  // items).
  void run_lanes(size_t items, size_t lanes, size_t local = 64);
  void run_2d(size_t width, size_t height, size_t local_x = 8, size_t local_y = 8);
  const std::string& name() const { return name_; }

 private:
  template <class T, class = void>
  struct binds_itself : std::false_type {};
  template <class T>
  struct binds_itself<T, std::void_t<decltype(std::declval<const T&>().bind_to(std::declval<Kernel&>(), 0u))>>
      : std::true_type {};
  template <class T>
  cl_uint bind(cl_uint index, const T& value) {
    if constexpr (binds_itself<T>::value) {
      return value.bind_to(*this, index);
    } else {
      set_arg(index, value);
      return 1;
    }
  }

  void launch(cl_uint dims, const size_t* global, const size_t* local, size_t items);
  Context* context_;
  cl_kernel kernel_;
  std::string name_;
};

// Checks a buffer of `bytes` against the device's largest allocation (CL_DEVICE_MAX_MEM_ALLOC_SIZE)
// before it is asked for; after a failed clCreateBuffer (`err`), says what was asked for and
// what the device allows instead of the bare error code. Throws DeviceError.
void check_buffer_size(const Context& context, size_t count, size_t element_size);
[[noreturn]] void throw_buffer_error(const Context& context, size_t bytes, cl_int err);

// A device buffer of `count` elements of plain type T.
template <class T>
class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, size_t count, cl_mem_flags flags = CL_MEM_READ_WRITE)
      : context_(&context), count_(count) {
    cl_int err = CL_SUCCESS;
    check_buffer_size(context, count, sizeof(T));
    // A zero-sized buffer is invalid in OpenCL; keep one element so kernels always get a handle.
    mem_ = clCreateBuffer(context.handle(), flags, sizeof(T) * (count ? count : 1), nullptr, &err);
    if (err != CL_SUCCESS) throw_buffer_error(context, sizeof(T) * (count ? count : 1), err);
  }
  Buffer(Context& context, const std::vector<T>& data, cl_mem_flags flags = CL_MEM_READ_WRITE)
      : Buffer(context, data.size(), flags) {
    write(data);
  }
  ~Buffer() {
    if (mem_) clReleaseMemObject(mem_);
  }
  Buffer(Buffer&& o) noexcept { *this = std::move(o); }
  Buffer& operator=(Buffer&& o) noexcept {
    if (this != &o) {
      if (mem_) clReleaseMemObject(mem_);
      context_ = o.context_;
      mem_ = o.mem_;
      count_ = o.count_;
      o.mem_ = nullptr;
      o.count_ = 0;
    }
    return *this;
  }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  size_t size() const { return count_; }
  cl_mem handle() const { return mem_; }
  Context& context() const { return *context_; }

  void write(const T* data, size_t count, size_t offset = 0) {
    if (count == 0) return;
    ScopedTimer t(context_->stats(), "transfer/write");
    cl_check(clEnqueueWriteBuffer(context_->queue(), mem_, CL_TRUE, offset * sizeof(T),
                                  count * sizeof(T), data, 0, nullptr, nullptr),
             "clEnqueueWriteBuffer");
  }
  void write(const std::vector<T>& data) { write(data.data(), data.size()); }
  void read(T* out, size_t count, size_t offset = 0) const {
    if (count == 0) return;
    ScopedTimer t(context_->stats(), "transfer/read");
    cl_check(clEnqueueReadBuffer(context_->queue(), mem_, CL_TRUE, offset * sizeof(T),
                                 count * sizeof(T), out, 0, nullptr, nullptr),
             "clEnqueueReadBuffer");
  }
  std::vector<T> read() const {
    std::vector<T> out(count_);
    read(out.data(), count_);
    return out;
  }
  // Host access to the first `count` elements while the returned view lives. On CPU devices
  // with CL_MEM_ALLOC_HOST_PTR buffers this is zero-copy: the host works on the device memory.
  class Mapping {
   public:
    Mapping(const Buffer& b, T* data) : buffer_(&b), data_(data) {}
    ~Mapping() {
      if (data_) clEnqueueUnmapMemObject(buffer_->context_->queue(), buffer_->mem_, data_, 0, nullptr, nullptr);
    }
    Mapping(const Mapping&) = delete;
    Mapping& operator=(const Mapping&) = delete;
    T* data() const { return data_; }
    T& operator[](size_t i) const { return data_[i]; }

   private:
    const Buffer* buffer_;
    T* data_;
  };
  Mapping map(size_t count, cl_map_flags flags = CL_MAP_READ | CL_MAP_WRITE) const {
    ScopedTimer t(context_->stats(), "transfer/map");
    cl_int err = CL_SUCCESS;
    void* p = clEnqueueMapBuffer(context_->queue(), mem_, CL_TRUE, flags, 0, sizeof(T) * (count ? count : 1), 0,
                                 nullptr, nullptr, &err);
    cl_check(err, "clEnqueueMapBuffer");
    return Mapping(*this, static_cast<T*>(p));
  }

  void fill(const T& value) {
    if (count_ == 0) return;
    cl_check(clEnqueueFillBuffer(context_->queue(), mem_, &value, sizeof(T), 0, count_ * sizeof(T),
                                 0, nullptr, nullptr),
             "clEnqueueFillBuffer");
  }

  // Copies the first `count` elements into dst on the device (queued in order).
  void copy_to(Buffer<T>& dst, size_t count) const {
    if (count == 0) return;
    cl_check(clEnqueueCopyBuffer(context_->queue(), mem_, dst.mem_, 0, 0, count * sizeof(T), 0, nullptr, nullptr),
             "clEnqueueCopyBuffer");
  }

 private:
  Context* context_ = nullptr;
  cl_mem mem_ = nullptr;
  size_t count_ = 0;
};

// Build options the engine always passes (OpenCL C 1.2: what PoCL and every vendor support).
std::string program_build_options(const Defines& defines);

}  // namespace gdr
