#include "render/software_renderer.h"

#include "render/zone_scene.h"

#include "render/irrlicht_library.h"

// Not <irrlicht.h>: through the scene manager it includes irrXML.h, whose `xmlChar<T>()`
// constructor declarations are ill-formed in C++20 (GCC rejects them). Only the device, the
// driver and matrix4 are used; the device comes from irrlicht_library.h (Irrlicht is opened on
// first use, not linked), so nothing here may name one of Irrlicht's exported symbols.
#include <IEventReceiver.h>
#include <IVideoDriver.h>
#include <IrrlichtDevice.h>
#include <SIrrCreationParameters.h>
#include <matrix4.h>

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <glm/trigonometric.hpp>

namespace pvs::ui {

namespace {

// Points fd 1 at /dev/null while alive: the console device writes "ESC c ESC [7l" (terminal
// reset, no line wrap) to stdout when created and "ESC c" when destroyed.
class StdoutSilenced {
public:
    StdoutSilenced()
    {
        std::fflush(stdout);
        saved_ = ::dup(STDOUT_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0)
            redirected_ = ::dup2(null, STDOUT_FILENO) >= 0;
        if (null >= 0)
            ::close(null);
    }
    ~StdoutSilenced()
    {
        std::fflush(stdout);
        if (redirected_)
            ::dup2(saved_, STDOUT_FILENO);
        if (saved_ >= 0)
            ::close(saved_);
    }
    StdoutSilenced(const StdoutSilenced&) = delete;
    StdoutSilenced& operator=(const StdoutSilenced&) = delete;

private:
    int saved_ = -1;
    bool redirected_ = false;
};

// Restores the handlers the console device installs for SIGINT, SIGTERM and SIGABRT: they
// would call closeDevice() on the last device created (a dangling pointer once it is dropped)
// instead of ending the program.
class SignalHandlersKept {
public:
    SignalHandlersKept()
    {
        for (size_t i = 0; i < kSignals.size(); ++i)
            saved_ok_[i] = ::sigaction(kSignals[i], nullptr, &saved_[i]) == 0;
    }
    ~SignalHandlersKept()
    {
        for (size_t i = 0; i < kSignals.size(); ++i)
            if (saved_ok_[i])
                ::sigaction(kSignals[i], &saved_[i], nullptr);
    }
    SignalHandlersKept(const SignalHandlersKept&) = delete;
    SignalHandlersKept& operator=(const SignalHandlersKept&) = delete;

private:
    static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGABRT};
    std::array<struct sigaction, 3> saved_{};
    std::array<bool, 3> saved_ok_{};
};

// Keeps Irrlicht's log messages (warnings and errors) for our exceptions instead of letting it
// print them to stdout.
class LogCatcher : public irr::IEventReceiver {
public:
    bool OnEvent(const irr::SEvent& event) override
    {
        if (event.EventType != irr::EET_LOG_TEXT_EVENT)
            return false;
        if (event.LogEvent.Text)
            last_ = event.LogEvent.Text;
        return true;
    }
    const std::string& last() const { return last_; }

private:
    std::string last_;
};

double ms_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

struct SoftwareRenderer::Impl {
    uint32_t width = 0, height = 0;
    LogCatcher log; // before device: the device points at it until dropped
    irr::IrrlichtDevice* device = nullptr;
    irr::video::IVideoDriver* driver = nullptr;
    irr::video::ITexture* target = nullptr;
    std::unique_ptr<ZoneScene> scene;
    RenderStats stats;

    ~Impl()
    {
        scene.reset(); // removes its textures while the driver exists
        if (device) {
            StdoutSilenced quiet;
            SignalHandlersKept handlers;
            device->drop();
        }
    }

    std::string irrlicht_said() const { return log.last().empty() ? "" : " (Irrlicht: " + log.last() + ")"; }
};

SoftwareRenderer::SoftwareRenderer(uint32_t width, uint32_t height) : impl_(std::make_unique<Impl>())
{
    if (width == 0 || height == 0 || width > 8192 || height > 8192)
        throw std::runtime_error("render size " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is out of range (1 .. 8192 each)");
    Impl& s = *impl_;
    s.width = width;
    s.height = height;

    irr::SIrrlichtCreationParameters params;
    params.DeviceType = irr::EIDT_CONSOLE;
    params.DriverType = irr::video::EDT_BURNINGSVIDEO;
    params.WindowSize = irr::core::dimension2d<irr::u32>(width, height); // the depth buffer's size too
    params.Bits = 32;
    params.AntiAlias = 0;
    params.Vsync = false;
    params.EventReceiver = &s.log;
    params.LoggingLevel = irr::ELL_WARNING;
    {
        StdoutSilenced quiet;
        SignalHandlersKept handlers;
        s.device = create_irrlicht_device(params);
    }
    if (!s.device)
        throw std::runtime_error("cannot create Irrlicht's console device with Burning's Video" + s.irrlicht_said());
    s.driver = s.device->getVideoDriver();
    if (!s.driver || s.driver->getDriverType() != irr::video::EDT_BURNINGSVIDEO)
        throw std::runtime_error("Irrlicht has no Burning's Video driver" + s.irrlicht_said());

    // Material textures: 32-bit, mipmapped (the textured picture only; the other modes draw no
    // texture at all).
    s.driver->setTextureCreationFlag(irr::video::ETCF_ALWAYS_32_BIT, true);
    s.driver->setTextureCreationFlag(irr::video::ETCF_CREATE_MIP_MAPS, true);
    s.target = s.driver->addRenderTargetTexture(irr::core::dimension2d<irr::u32>(width, height), "pvscope/target",
                                                irr::video::ECF_A8R8G8B8);
    if (!s.target || s.target->getColorFormat() != irr::video::ECF_A8R8G8B8 ||
        s.target->getSize() != irr::core::dimension2d<irr::u32>(width, height))
        throw std::runtime_error("Burning's Video cannot make a " + std::to_string(width) + "x" +
                                 std::to_string(height) + " 32-bit render target" + s.irrlicht_said());
}

SoftwareRenderer::~SoftwareRenderer() = default;

uint32_t SoftwareRenderer::width() const { return impl_->width; }
uint32_t SoftwareRenderer::height() const { return impl_->height; }
const RenderStats& SoftwareRenderer::last_stats() const { return impl_->stats; }
void SoftwareRenderer::forget_zone() { impl_->scene.reset(); }

Image SoftwareRenderer::render(const Zone& zone, const Camera& camera, const std::vector<uint32_t>& visible_regions,
                               RenderMode mode, std::span<const uint32_t> region_tints)
{
    return draw_frame(zone, camera, visible_regions, mode, region_tints, false);
}

Image SoftwareRenderer::render_ids_behind_translucent(const Zone& zone, const Camera& camera,
                                                      const std::vector<uint32_t>& visible_regions)
{
    return draw_frame(zone, camera, visible_regions, RenderMode::IdBuffer, {}, true);
}

Image SoftwareRenderer::draw_frame(const Zone& zone, const Camera& camera, const std::vector<uint32_t>& visible_regions,
                                   RenderMode mode, std::span<const uint32_t> region_tints, bool opaque_only)
{
    Impl& s = *impl_;
    if (mode == RenderMode::IdBuffer && zone.mesh.faces.size() > kMaxIdFaces)
        throw std::runtime_error("the ID buffer encodes at most " + std::to_string(kMaxIdFaces) +
                                 " faces (21 bits, see ui/software_renderer.h); this zone has " +
                                 std::to_string(zone.mesh.faces.size()));
    s.stats = RenderStats{};

    const auto build_start = std::chrono::steady_clock::now();
    if (!s.scene || !s.scene->built_from(zone)) {
        s.scene.reset();
        s.scene = std::make_unique<ZoneScene>(zone, *s.driver);
        s.stats.scene_ms = ms_since(build_start);
    }

    const auto draw_start = std::chrono::steady_clock::now();
    // The same view volume as camera.view_projection(), in Irrlicht's frame, built the way
    // Irrlicht's own camera node does (CCameraSceneNode: buildCameraLookAtMatrixLH with the up
    // vector nudged when it is parallel to the view, buildProjectionMatrixPerspectiveFovLH with
    // the vertical field of view). The node itself is not used: its header cannot be included
    // (see above). Camera::forward() clamps the pitch short of straight up/down.
    const irr::core::vector3df eye = to_irrlicht(camera.position);
    const irr::core::vector3df target = to_irrlicht(camera.position + camera.forward());
    irr::core::vector3df up(0.0f, 1.0f, 0.0f);
    if (irr::core::equals(std::fabs((target - eye).normalize().dotProduct(up)), 1.0f))
        up.X += 0.5f;
    irr::core::matrix4 view, projection;
    view.buildCameraLookAtMatrixLH(eye, target, up);
    projection.buildProjectionMatrixPerspectiveFovLH(glm::radians(camera.fov_y_degrees), camera.aspect,
                                                     camera.near_distance, camera.far_distance);

    // Never endScene(): on the console device it would print the frame to stdout as ASCII art.
    s.driver->beginScene(false, false);
    s.driver->setRenderTarget(s.target, true, true, irr::video::SColor(0, 0, 0, 0));
    s.driver->setTransform(irr::video::ETS_PROJECTION, projection);
    s.driver->setTransform(irr::video::ETS_VIEW, view);
    s.driver->setTransform(irr::video::ETS_WORLD, irr::core::matrix4()); // identity (not Irrlicht's exported IdentityMatrix)
    const ZoneScene::DrawStats drawn = s.scene->draw(visible_regions, mode, region_tints, opaque_only);
    s.driver->setRenderTarget(nullptr, false, false);

    Image image;
    image.width = s.width;
    image.height = s.height;
    image.rgba.resize(size_t(s.width) * s.height * 4);
    const auto* base = static_cast<const uint8_t*>(s.target->lock(irr::video::ETLM_READ_ONLY));
    if (!base)
        throw std::runtime_error("cannot read back the render target" + s.irrlicht_said());
    const uint32_t pitch = s.target->getPitch();
    // See the header: Burning's Video returns each channel of a flat colour as written or one
    // less; colours in IdBuffer and RegionColors images are all written with odd channels, so
    // setting the low bit back gives exactly what was written. The background stays 0.
    const bool exact_colours = mode == RenderMode::IdBuffer || mode == RenderMode::RegionColors;
    for (uint32_t y = 0; y < s.height; ++y) {
        const uint8_t* row = base + size_t(y) * pitch;
        uint8_t* out = image.rgba.data() + size_t(y) * s.width * 4;
        for (uint32_t x = 0; x < s.width; ++x) {
            uint32_t argb;
            std::memcpy(&argb, row + 4 * size_t(x), 4);
            uint32_t rgb = argb & 0xFFFFFFu;
            if (exact_colours && rgb != 0)
                rgb |= 0x010101u;
            out[4 * x + 0] = uint8_t(rgb >> 16);
            out[4 * x + 1] = uint8_t(rgb >> 8);
            out[4 * x + 2] = uint8_t(rgb);
            out[4 * x + 3] = 255;
        }
    }
    s.target->unlock();

    s.stats.draw_ms = ms_since(draw_start);
    s.stats.faces_drawn = drawn.faces;
    s.stats.triangles_drawn = drawn.triangles;
    return image;
}

} // namespace pvs::ui
