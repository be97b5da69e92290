#include "ui/gui/inspector_app.h"

#include "ui/gui/fps_report.h"

#include "ui/gui/inspector_state.h"
#include "ui/gui/panels.h"

#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// Only OpenGL 1.1 calls (textures, read-back) are made here, straight from libGL; the ImGui
// backend loads what it needs itself.
#include <GL/gl.h>
#include <stb_image_write.h> // Debian's libstb, which ImGui links already

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace pvs::gui {

namespace {

// --report-fps: frames drawn before the timed ones (the windows sized, the scene built).
constexpr size_t kWarmupFrames = 10;

void glfw_error(int code, const char* description) { std::fprintf(stderr, "pvscope: GLFW error %d: %s\n", code, description); }

// Owns GLFW, the window and the ImGui context with its backends; tears them down in order.
struct Platform {
    GLFWwindow* window = nullptr;
    bool imgui = false, glfw_backend = false, gl_backend = false;
    std::vector<std::string> dropped; // paths dropped on the window, not yet opened

    ~Platform()
    {
        if (gl_backend)
            ImGui_ImplOpenGL3_Shutdown();
        if (glfw_backend)
            ImGui_ImplGlfw_Shutdown();
        if (imgui)
            ImGui::DestroyContext();
        if (window)
            glfwDestroyWindow(window);
        glfwTerminate();
    }
};

void on_drop(GLFWwindow* window, int count, const char** paths)
{
    auto* platform = static_cast<Platform*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i)
        platform->dropped.emplace_back(paths[i]);
}

bool open_platform(Platform& platform, const InspectorOptions& options)
{
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit())
        return false;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    platform.window = glfwCreateWindow(int(options.width), int(options.height), "pvscope", nullptr, nullptr);
    if (!platform.window)
        return false;
    glfwMakeContextCurrent(platform.window);
    glfwSwapInterval(options.screenshot.empty() && !options.report_fps ? 1 : 0);
    glfwSetWindowUserPointer(platform.window, &platform);
    glfwSetDropCallback(platform.window, on_drop);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    platform.imgui = true;
    ImGui::GetIO().IniFilename = nullptr; // the layout is tiled from the window size
    ImGui::StyleColorsDark();
    platform.glfw_backend = ImGui_ImplGlfw_InitForOpenGL(platform.window, true);
    platform.gl_backend = platform.glfw_backend && ImGui_ImplOpenGL3_Init("#version 130");
    return platform.gl_backend;
}

// Presents the window on a thread of its own, so the next frame's cull, picture and overlays
// (CPU work) run while a software GL driver (Mesa's llvmpipe here) rasterises the panels and
// swaps. The GL context is current on one thread at a time: present() hands it over, and
// reclaim() waits for the swap and takes it back before the main thread's next GL call.
class Presenter {
public:
    Presenter(GLFWwindow* window, bool finish) : window_(window), finish_(finish), thread_([this] { run(); }) {}
    ~Presenter()
    {
        reclaim();
        {
            std::lock_guard lock(mutex_);
            quit_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    void present()
    {
        glfwMakeContextCurrent(nullptr);
        {
            std::lock_guard lock(mutex_);
            pending_ = true;
            owned_ = false;
        }
        waited_ms_ = 0;
        wake_.notify_all();
    }
    // Waits for the swap in flight, if any, and makes the context current here again.
    void reclaim()
    {
        const auto start = std::chrono::steady_clock::now();
        std::unique_lock lock(mutex_);
        if (owned_)
            return;
        wake_.wait(lock, [this] { return !pending_; });
        last_present_ms_ = present_ms_;
        lock.unlock();
        glfwMakeContextCurrent(window_);
        owned_ = true;
        waited_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    // The last finished swap's time (with glFinish in timed runs), and how long the main thread
    // waited for swaps since its last present(), in ms. Main thread only.
    double last_present_ms() const { return last_present_ms_; }
    double waited_ms() const { return waited_ms_; }

private:
    void run()
    {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return pending_ || quit_; });
            if (quit_)
                return;
            lock.unlock();
            const auto start = std::chrono::steady_clock::now();
            glfwMakeContextCurrent(window_);
            glfwSwapBuffers(window_);
            if (finish_)
                glFinish();
            glfwMakeContextCurrent(nullptr);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            lock.lock();
            present_ms_ = ms;
            pending_ = false;
            wake_.notify_all();
        }
    }

    GLFWwindow* window_;
    bool finish_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool pending_ = false, quit_ = false; // guarded by mutex_
    double present_ms_ = 0;               // guarded by mutex_
    bool owned_ = true;                   // the main thread holds the context (set by it alone)
    double last_present_ms_ = 0, waited_ms_ = 0;
    std::thread thread_;
};

// The viewport's texture: one GL texture, re-specified when the picture's size changes.
struct ViewportTexture {
    GLuint id = 0;
    uint32_t width = 0, height = 0;

    ~ViewportTexture()
    {
        if (id)
            glDeleteTextures(1, &id);
    }
    ImTextureID upload(const ui::Image& image)
    {
        if (!id) {
            glGenTextures(1, &id);
            glBindTexture(GL_TEXTURE_2D, id);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        glBindTexture(GL_TEXTURE_2D, id);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        const auto w = GLsizei(image.width), h = GLsizei(image.height);
        if (image.width != width || image.height != height) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
            width = image.width;
            height = image.height;
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        }
        return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(id));
    }
};

// Writes the whole window as the back buffer holds it now to an RGB PNG (no alpha: a window
// has none, and RGB at stb's highest compression keeps a README screenshot small).
bool save_window_png(GLFWwindow* window, const std::string& path)
{
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    const size_t row = size_t(width) * 3;
    std::vector<uint8_t> bottom_up(row * size_t(height)), top_down(bottom_up.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
    for (size_t y = 0; y < size_t(height); ++y)
        std::copy_n(bottom_up.data() + (size_t(height) - 1 - y) * row, row, top_down.data() + y * row);
    stbi_write_png_compression_level = 9;
    return stbi_write_png(path.c_str(), width, height, 3, top_down.data(), int(row)) != 0;
}

int run_loop(Platform& platform, InspectorState& state, const InspectorOptions& options)
{
    FpsReport fps(kWarmupFrames);
    ViewportTexture texture;
    Presenter presenter(platform.window, options.report_fps);
    InspectorPanels panels;
    panels.viewport.upload = [&](const ui::Image& image) {
        presenter.reclaim();
        return texture.upload(image);
    };
    panels.zone.open_path = options.zone_path;
    if (options.bake)
        panels.bake.request = *options.bake;
    panels.compare.expanded = options.compare;
    if (!options.stability_case.empty()) {
        panels.stability.expanded = true;
        panels.stability.table = gen::run_case_table(panels.stability.options); // well under a second
    }
    // Scripted runs (screenshots, timings) leave the user's recent files alone.
    if (options.screenshot.empty()) {
        panels.file.recent = RecentFiles(default_recent_files_path());
        panels.file.recent.load();
        std::error_code error;
        const std::filesystem::path absolute = std::filesystem::absolute(options.zone_path, error);
        if (!options.zone_path.empty() && !error)
            panels.file.recent.add(absolute.lexically_normal().string());
    }
    int frames = 0;
    uint64_t titled_zone = 0;
    while (!glfwWindowShouldClose(platform.window)) {
        glfwPollEvents();
        for (const std::string& path : platform.dropped) {
            panels.zone.open_path = path;
            open_zone_file(state, panels.file, path);
        }
        platform.dropped.clear();
        if (state.has_zone() && state.zone_generation() != titled_zone) {
            titled_zone = state.zone_generation();
            glfwSetWindowTitle(platform.window, ("pvscope - " + state.zone().source.path).c_str());
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        // Scripted frames get a fixed time step, so a screenshot does not depend on the machine,
        // and no mouse: nobody holds it (Xvfb's pointer rests mid-screen, where its hover text
        // would cover the picture).
        const bool scripted = !options.screenshot.empty() || options.report_fps;
        if (scripted)
            ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        if (options.report_fps && options.cameras > 0 && !fps.flying() && state.has_zone())
            fps.plan_flight(state, options.cameras, options.camera_seed);
        if (fps.flying())
            state.view_camera() = fps.next_camera();
        using Clock = std::chrono::steady_clock;
        const auto ms_since = [](Clock::time_point t) {
            return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
        };
        FpsReport::Phases phases;
        auto phase_start = Clock::now();
        ImGui::NewFrame();
        draw_inspector(state, panels, scripted ? 1.0f / 30.0f : ImGui::GetIO().DeltaTime);
        ImGui::Render();
        phases.inspector_ms = ms_since(phase_start);
        phases.inspector_wait_ms = presenter.waited_ms();

        presenter.reclaim();
        phase_start = Clock::now();
        int width = 0, height = 0;
        glfwGetFramebufferSize(platform.window, &width, &height);
        glViewport(0, 0, width, height);
        glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        phases.gl_ms = ms_since(phase_start);

        const bool working = state.bake_job().status() == JobStatus::Running ||
                             state.compare_job().status() == JobStatus::Running || state.explanation_running();
        if (scripted && working && frames == 0) {
            presenter.present();
            continue; // a scripted bake: the timed or screenshot frames start once it is done
        }
        if (options.pick_centre && frames == 1)
            state.pick(state.image().width / 2, state.image().height / 2);
        if (options.report_fps) {
            // The frame ends when its picture is handed over; the swap overlaps the next frame, and
            // the next frame's time holds any wait for it.
            if (size_t(frames + 1) >= fps.frames_needed(size_t(options.frames)) && !options.screenshot.empty() &&
                !save_window_png(platform.window, options.screenshot))
                return 1;
            phases.present_ms = presenter.last_present_ms();
            phases.wait_ms = presenter.waited_ms();
            presenter.present();
            fps.lap(state, phases);
            if (size_t(++frames) >= fps.frames_needed(size_t(options.frames))) {
                fps.print(state);
                return 0;
            }
            continue;
        }
        if (!options.screenshot.empty() && ++frames >= options.frames) {
            if (!save_window_png(platform.window, options.screenshot)) {
                std::fprintf(stderr, "pvscope: error: cannot write %s\n", options.screenshot.c_str());
                return 1;
            }
            std::printf("pvscope: wrote %s (%d frames)\n", options.screenshot.c_str(), frames);
            return 0;
        }
        presenter.present();
    }
    return 0;
}

} // namespace

int run_inspector(const InspectorOptions& options)
{
    InspectorState state;
    if (!options.stability_case.empty()) {
        const size_t colon = options.stability_case.find(':');
        const std::string name = options.stability_case.substr(0, colon);
        const std::string method = colon == std::string::npos ? "portal-full" : options.stability_case.substr(colon + 1);
        if (!state.open_stability_case(name, method)) {
            std::fprintf(stderr, "pvscope: error: --case: %s\n", state.error().c_str());
            return 1;
        }
    } else if (options.zone_path.empty())
        state.open_demo();
    else if (!state.open_zone(options.zone_path, options.zone_load)) {
        std::fprintf(stderr, "pvscope: error: %s\n", state.error().c_str());
        return 1;
    }
    state.cull_mode = options.cull_mode;
    state.far_clip = options.far_clip;
    state.overlays = options.overlays;
    state.set_memory_probe(options.memory_probe);
    if (options.bake)
        state.start_bake(*options.bake);
    if (options.compare) {
        const ComparePanel defaults;
        ui::CompareOptions compare;
        compare.reference_samples = uint64_t(defaults.reference_samples);
        compare.cameras = size_t(defaults.cameras);
        state.start_compare(compare);
    }
    if (options.bsp_node >= 0 && size_t(options.bsp_node) < state.zone().tree.nodes.size())
        state.selected_node = options.bsp_node;
    if (options.why) {
        state.select_region(int32_t((*options.why)[0]));
        if (!state.request_explanation((*options.why)[0], (*options.why)[1])) {
            std::fprintf(stderr, "pvscope: error: --why: %s\n", state.error().c_str());
            return 1;
        }
    }
    if (options.camera) {
        const auto& [x, y, z, yaw, pitch] = *options.camera;
        Camera& view = state.view_camera();
        view.position = {x, y, z};
        view.yaw_degrees = yaw;
        view.pitch_degrees = pitch;
    }

    Platform platform;
    if (!open_platform(platform, options)) {
        std::fprintf(stderr, "pvscope: error: cannot open a window with an OpenGL 3 context "
                             "(no display? try xvfb-run, or use a subcommand such as `pvscope info`)\n");
        return 1;
    }
    try {
        return run_loop(platform, state, options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pvscope: error: %s\n", e.what());
        return 1;
    }
}

} // namespace pvs::gui
