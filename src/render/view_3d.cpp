#include "rigdesign/render/view_3d.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rigdesign/render/png_writer.hpp"

namespace rigdesign::render {
namespace {

// Each output pixel averages a kSupersample x kSupersample block of rendered pixels: cheap
// anti-aliasing that needs nothing from the GL implementation.
constexpr int kSupersample = 2;
// Depth-buffer bits: 24 resolves a few micrometres over an orthographic box metres deep.
constexpr GLint kDepthBits = 24;
constexpr double kGridSpacing = 1.0;       // [m]
constexpr double kAxisLength = 0.5;        // [m]
constexpr double kArrowHeadLength = 0.08;  // [m]
constexpr double kArrowHeadRadius = 0.03;  // [m]
constexpr int kArrowHeadSides = 16;        // polygon sides of an arrow head's cone
constexpr double kFrameMargin = 0.04;      // blank border, as a share of the framed size
constexpr double kDepthSlack = 1.0;        // [m] beyond the farthest vertex, for the clip box
constexpr float kGridLineWidth = 1.0F;     // [output px]
constexpr float kAxisLineWidth = 2.0F;     // [output px]
constexpr Rgb kFloorGridColour{0.80, 0.80, 0.80};
constexpr std::array<Rgb, 3> kAxisColours = {{{0.85, 0.10, 0.10},    // x red
                                              {0.10, 0.60, 0.10},    // y green
                                              {0.10, 0.20, 0.85}}};  // z blue
// Classic isometric: seen along a cube's diagonal, elevation atan(1/sqrt 2) = 35.26 deg, from
// the front-left (azimuth 45 deg) so the robot's front and left side face the viewer.
constexpr double kIsoAzimuth = std::numbers::pi / 4;  // [rad]
const double kIsoElevation = std::atan(1.0 / std::numbers::sqrt2);
// Fixed-function lighting: a directional light from above-left of the viewer plus ambient
// light, so faces keep distinguishable shades and none goes black.
constexpr std::array<GLfloat, 4> kLightDirectionEye = {-0.4F, 0.6F, 1.0F, 0.0F};
constexpr std::array<GLfloat, 4> kAmbientLight = {0.40F, 0.40F, 0.40F, 1.0F};
constexpr std::array<GLfloat, 4> kDiffuseLight = {0.60F, 0.60F, 0.60F, 1.0F};
constexpr std::array<GLfloat, 4> kNoLight = {0.0F, 0.0F, 0.0F, 1.0F};

// An OSMesa context drawing into its own RGBA buffer (rows bottom-up, as OpenGL reads them),
// current for the object's lifetime.
class OffscreenContext {
 public:
  OffscreenContext(int width, int height) : buffer_(static_cast<std::size_t>(width) * height * 4) {
    context_ = OSMesaCreateContextExt(OSMESA_RGBA, kDepthBits, 0, 0, nullptr);
    if (context_ == nullptr) {
      throw std::runtime_error(
          "3D view: could not create an OSMesa off-screen OpenGL context (is Mesa's libOSMesa "
          "working?)");
    }
    if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height) == 0) {
      OSMesaDestroyContext(context_);
      throw std::runtime_error("3D view: OSMesa could not draw a " + std::to_string(width) + " x " +
                               std::to_string(height) + " px image");
    }
  }
  ~OffscreenContext() {
    // Released first, so no destroyed context stays current on this thread.
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// The rendered pixels once glFinish has returned.
  const std::vector<GLubyte>& pixels() const { return buffer_; }

 private:
  std::vector<GLubyte> buffer_;
  OSMesaContext context_ = nullptr;
};

// An orthographic camera: p_eye = R_eye_robot * p_robot - centre_eye, eye x right, y up and
// z toward the viewer; the clip box is [-half_width, half_width] x [-half_height,
// half_height] x [-depth, depth].
struct Camera {
  model::Mat3 R_eye_robot = model::Mat3::Identity();
  model::Vec3 centre_eye = model::Vec3::Zero();
  double half_width = 1.0;   // [m]
  double half_height = 1.0;  // [m]
  double depth = 1.0;        // [m]
};

model::Mat3 view_rotation(Viewpoint viewpoint) {
  model::Mat3 R_eye_robot;
  if (viewpoint == Viewpoint::top) {
    // Seen from above, REP-103: forward (+x) up the image, left (+y) to the left.
    R_eye_robot << 0, -1, 0,  //
        1, 0, 0,              //
        0, 0, 1;
    return R_eye_robot;
  }
  const model::Vec3 toward_viewer(std::cos(kIsoElevation) * std::cos(kIsoAzimuth),
                                  std::cos(kIsoElevation) * std::sin(kIsoAzimuth),
                                  std::sin(kIsoElevation));
  const model::Vec3 right = model::Vec3::UnitZ().cross(toward_viewer).normalized();
  const model::Vec3 up = toward_viewer.cross(right);
  R_eye_robot.row(0) = right.transpose();
  R_eye_robot.row(1) = up.transpose();
  R_eye_robot.row(2) = toward_viewer.transpose();
  return R_eye_robot;
}

// Everything the picture must hold besides the floor: the meshes and the axis arrows.
Eigen::AlignedBox3d content_box(const std::vector<ColouredMesh>& meshes) {
  Eigen::AlignedBox3d content(model::Vec3::Zero());
  content.extend(model::Vec3::Constant(kAxisLength));
  for (const ColouredMesh& coloured : meshes) {
    for (const model::Vec3& vertex : coloured.mesh.vertices) content.extend(vertex);
  }
  return content;
}

// [m] half-width of the floor square to frame and grid: the extent, or else the content's
// reach rounded up to whole grid cells, so the grid ends on a line.
double floor_half_width(const Eigen::AlignedBox3d& content, double extent) {
  if (extent > 0) return extent;
  const double reach =
      std::max({-content.min().x(), content.max().x(), -content.min().y(), content.max().y()});
  return std::max(kGridSpacing, kGridSpacing * std::ceil(reach / kGridSpacing));
}

// The box (robot frame) the picture frames: the floor square, as tall as the content.
Eigen::AlignedBox3d framed_box(const Eigen::AlignedBox3d& content, double floor_half) {
  return Eigen::AlignedBox3d(model::Vec3(-floor_half, -floor_half, content.min().z()),
                             model::Vec3(floor_half, floor_half, content.max().z()));
}

Camera frame_camera(const std::vector<ColouredMesh>& meshes, const View3dSettings& settings,
                    const Eigen::AlignedBox3d& box) {
  Camera camera;
  camera.R_eye_robot = view_rotation(settings.viewpoint);
  camera.centre_eye = camera.R_eye_robot * box.center();
  // A box projects symmetrically about its centre, so its corners give the half sizes.
  double half_width = 0.0;
  double half_height = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const model::Vec3 offset =
        camera.R_eye_robot * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) -
        camera.centre_eye;
    half_width = std::max(half_width, std::abs(offset.x()));
    half_height = std::max(half_height, std::abs(offset.y()));
  }
  half_width *= 1 + 2 * kFrameMargin;
  half_height *= 1 + 2 * kFrameMargin;
  // Widen whichever side is short of the image's aspect ratio, so metres stay square.
  const double aspect = static_cast<double>(settings.width) / settings.height;
  camera.half_width = std::max(half_width, half_height * aspect);
  camera.half_height = camera.half_width / aspect;

  double depth = 0.0;
  const auto reach_depth = [&](const model::Vec3& p_robot) {
    depth = std::max(depth, std::abs((camera.R_eye_robot * p_robot - camera.centre_eye).z()));
  };
  for (const ColouredMesh& coloured : meshes) {
    for (const model::Vec3& vertex : coloured.mesh.vertices) reach_depth(vertex);
  }
  for (int corner = 0; corner < 8; ++corner) {
    reach_depth(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  }
  camera.depth = depth + kDepthSlack;
  return camera;
}

void set_up_pipeline(const Camera& camera, int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(1.0F, 1.0F, 1.0F, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-camera.half_width, camera.half_width, -camera.half_height, camera.half_height,
          -camera.depth, camera.depth);
  glMatrixMode(GL_MODELVIEW);
  // The light is placed while the model-view matrix is the identity, so it stays fixed to the
  // viewer whatever the viewpoint.
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, kLightDirectionEye.data());
  glLightfv(GL_LIGHT0, GL_AMBIENT, kAmbientLight.data());
  glLightfv(GL_LIGHT0, GL_DIFFUSE, kDiffuseLight.data());
  glLightfv(GL_LIGHT0, GL_SPECULAR, kNoLight.data());
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, kNoLight.data());
  // Translucent volumes show their inside faces; two-sided lighting lights those too.
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_LIGHT0);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glShadeModel(GL_FLAT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  Eigen::Matrix4d T_eye_robot = Eigen::Matrix4d::Identity();
  T_eye_robot.topLeftCorner<3, 3>() = camera.R_eye_robot;
  T_eye_robot.topRightCorner<3, 1>() = -camera.centre_eye;
  glLoadMatrixd(T_eye_robot.data());  // Eigen and OpenGL are both column-major
}

void draw_floor_grid(double grid_half) {
  glDisable(GL_LIGHTING);
  glLineWidth(kGridLineWidth * kSupersample);
  glColor3d(kFloorGridColour.r, kFloorGridColour.g, kFloorGridColour.b);
  const int cells = static_cast<int>(std::floor(grid_half / kGridSpacing));
  glBegin(GL_LINES);
  for (int k = -cells; k <= cells; ++k) {
    const double offset = k * kGridSpacing;
    glVertex3d(offset, -grid_half, 0);
    glVertex3d(offset, grid_half, 0);
    glVertex3d(-grid_half, offset, 0);
    glVertex3d(grid_half, offset, 0);
  }
  glEnd();
}

// Sends one triangle with its face normal (flat shading); degenerate ones are skipped.
void emit_triangle(const model::TriangleMesh& mesh, const std::array<int, 3>& triangle) {
  const model::Vec3& a = mesh.vertices[triangle[0]];
  const model::Vec3& b = mesh.vertices[triangle[1]];
  const model::Vec3& c = mesh.vertices[triangle[2]];
  const model::Vec3 normal = (b - a).cross(c - a);
  const double length = normal.norm();
  if (!(length > 0)) return;
  glNormal3d(normal.x() / length, normal.y() / length, normal.z() / length);
  glVertex3d(a.x(), a.y(), a.z());
  glVertex3d(b.x(), b.y(), b.z());
  glVertex3d(c.x(), c.y(), c.z());
}

bool is_opaque(const ColouredMesh& coloured) {
  return coloured.opacity >= 1.0;
}

void draw_opaque(const std::vector<ColouredMesh>& meshes) {
  glEnable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  for (const ColouredMesh& coloured : meshes) {
    if (!is_opaque(coloured)) continue;
    glColor4d(coloured.colour.r, coloured.colour.g, coloured.colour.b, 1.0);
    for (const auto& triangle : coloured.mesh.triangles) emit_triangle(coloured.mesh, triangle);
  }
  glEnd();
}

// Translucent triangles of every mesh, farthest first, blended without writing depth: the
// painter's order makes overlapping volumes composite correctly in most views.
void draw_translucent(const std::vector<ColouredMesh>& meshes, const model::Mat3& R_eye_robot) {
  struct Queued {
    double depth;  // eye z of the centroid [m]; smaller is farther
    const ColouredMesh* coloured;
    std::array<int, 3> triangle;
  };
  std::vector<Queued> queue;
  const model::Vec3 toward_viewer = R_eye_robot.row(2).transpose();
  for (const ColouredMesh& coloured : meshes) {
    if (is_opaque(coloured) || coloured.opacity <= 0) continue;
    for (const auto& triangle : coloured.mesh.triangles) {
      const model::Vec3 centroid =
          (coloured.mesh.vertices[triangle[0]] + coloured.mesh.vertices[triangle[1]] +
           coloured.mesh.vertices[triangle[2]]) /
          3;
      queue.push_back({toward_viewer.dot(centroid), &coloured, triangle});
    }
  }
  std::stable_sort(queue.begin(), queue.end(),
                   [](const Queued& a, const Queued& b) { return a.depth < b.depth; });
  glEnable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glDepthMask(GL_FALSE);
  glBegin(GL_TRIANGLES);
  for (const Queued& queued : queue) {
    const Rgb& colour = queued.coloured->colour;
    glColor4d(colour.r, colour.g, colour.b, queued.coloured->opacity);
    emit_triangle(queued.coloured->mesh, queued.triangle);
  }
  glEnd();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

// The robot frame's axes as arrows from the origin, drawn over everything: the origin lies
// inside the body, where depth testing would hide them.
void draw_axes() {
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glLineWidth(kAxisLineWidth * kSupersample);
  for (int axis = 0; axis < 3; ++axis) {
    const model::Vec3 along = model::Vec3::Unit(axis);
    const model::Vec3 across_1 = model::Vec3::Unit((axis + 1) % 3);
    const model::Vec3 across_2 = model::Vec3::Unit((axis + 2) % 3);
    const Rgb& colour = kAxisColours[axis];
    glColor3d(colour.r, colour.g, colour.b);
    const model::Vec3 head_base = (kAxisLength - kArrowHeadLength) * along;
    const model::Vec3 tip = kAxisLength * along;
    glBegin(GL_LINES);
    glVertex3d(0, 0, 0);
    glVertex3d(head_base.x(), head_base.y(), head_base.z());
    glEnd();
    // The head's cone and its base disc: between them they cover its outline from any side.
    for (const model::Vec3& centre : {tip, head_base}) {
      glBegin(GL_TRIANGLE_FAN);
      glVertex3d(centre.x(), centre.y(), centre.z());
      for (int side = 0; side <= kArrowHeadSides; ++side) {
        const double angle = 2 * std::numbers::pi * side / kArrowHeadSides;
        const model::Vec3 rim = head_base + kArrowHeadRadius * (std::cos(angle) * across_1 +
                                                                std::sin(angle) * across_2);
        glVertex3d(rim.x(), rim.y(), rim.z());
      }
      glEnd();
    }
  }
  glEnable(GL_DEPTH_TEST);
}

// Averages kSupersample x kSupersample blocks of the bottom-up rendering into an opaque,
// top-down RGBA image of the output size.
std::vector<std::uint8_t> downsample_top_down(const std::vector<GLubyte>& bottom_up, int width,
                                              int height) {
  const std::size_t rendered_width = static_cast<std::size_t>(width) * kSupersample;
  const std::size_t rendered_height = static_cast<std::size_t>(height) * kSupersample;
  constexpr unsigned kSamples = kSupersample * kSupersample;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
    for (std::size_t x = 0; x < static_cast<std::size_t>(width); ++x) {
      for (std::size_t channel = 0; channel < 3; ++channel) {
        unsigned sum = 0;
        for (std::size_t dy = 0; dy < kSupersample; ++dy) {
          const std::size_t row = rendered_height - 1 - (y * kSupersample + dy);
          for (std::size_t dx = 0; dx < kSupersample; ++dx) {
            sum += bottom_up[(row * rendered_width + x * kSupersample + dx) * 4 + channel];
          }
        }
        rgba[(y * width + x) * 4 + channel] =
            static_cast<std::uint8_t>((sum + kSamples / 2) / kSamples);
      }
      rgba[(y * width + x) * 4 + 3] = 255;  // the picture is opaque on white
    }
  }
  return rgba;
}

}  // namespace

std::vector<std::uint8_t> render_view_3d_pixels(const std::vector<ColouredMesh>& meshes,
                                                const View3dSettings& settings) {
  if (settings.width <= 0 || settings.height <= 0) {
    throw std::invalid_argument("3D view: the image size must be positive, got " +
                                std::to_string(settings.width) + " x " +
                                std::to_string(settings.height) + " px");
  }
  const int rendered_width = settings.width * kSupersample;
  const int rendered_height = settings.height * kSupersample;
  OffscreenContext context(rendered_width, rendered_height);

  const Eigen::AlignedBox3d content = content_box(meshes);
  const double grid_half = floor_half_width(content, settings.extent);
  const Camera camera = frame_camera(meshes, settings, framed_box(content, grid_half));
  set_up_pipeline(camera, rendered_width, rendered_height);
  draw_floor_grid(grid_half);
  draw_opaque(meshes);
  draw_translucent(meshes, camera.R_eye_robot);
  draw_axes();
  glFinish();
  return downsample_top_down(context.pixels(), settings.width, settings.height);
}

std::pair<double, double> ViewProjection::pixel(const model::Vec3& p_robot) const {
  const model::Vec3 eye = R_eye_robot * p_robot - centre_eye;
  return {(eye.x() / half_width + 1.0) * 0.5 * width, (1.0 - eye.y() / half_height) * 0.5 * height};
}

ViewProjection view_projection(const std::vector<ColouredMesh>& meshes,
                               const View3dSettings& settings) {
  const Eigen::AlignedBox3d content = content_box(meshes);
  const Camera camera = frame_camera(
      meshes, settings, framed_box(content, floor_half_width(content, settings.extent)));
  ViewProjection projection;
  projection.R_eye_robot = camera.R_eye_robot;
  projection.centre_eye = camera.centre_eye;
  projection.half_width = camera.half_width;
  projection.half_height = camera.half_height;
  projection.width = settings.width;
  projection.height = settings.height;
  projection.grid_spacing = kGridSpacing;
  return projection;
}

}  // namespace rigdesign::render
