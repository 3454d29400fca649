//! A headless OpenGL 3.3 core context on Mesa (llvmpipe) through EGL, without a window.
//!
//! | step | EGL call | what fails when the machine lacks it |
//! | --- | --- | --- |
//! | load `libEGL.so.1` at run time | `dlopen` | no libEGL (`libegl1`) |
//! | client extensions contain `EGL_MESA_platform_surfaceless` | `eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)` | no Mesa vendor (`libegl-mesa0`) |
//! | surfaceless display | `eglGetPlatformDisplay(0x31DD, EGL_DEFAULT_DISPLAY)` | |
//! | initialize | `eglInitialize` | no DRI driver (`libgl1-mesa-dri`) |
//! | desktop GL | `eglBindAPI(EGL_OPENGL_API)` | |
//! | config, context | `eglChooseConfig`, `eglCreateContext` (3.3 core) | driver without GL 3.3 core |
//! | current without a surface | `eglMakeCurrent(EGL_NO_SURFACE)` | `EGL_KHR_surfaceless_context` missing |
//!
//! Every failure comes back as a [`GlError`]; nothing here panics on a missing piece.
//! A context is bound to the thread that created it (EGL "current" is per thread), so
//! [`GlContext`] is neither `Send` nor `Sync`.

use std::fmt;
use std::marker::PhantomData;
use std::panic::{catch_unwind, AssertUnwindSafe};

use glow::HasContext;
use khronos_egl as egl;

/// `EGL_PLATFORM_SURFACELESS_MESA`, from the `EGL_MESA_platform_surfaceless` extension.
pub const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

/// The client extension that must be present for a surfaceless display.
pub const SURFACELESS_EXTENSION: &str = "EGL_MESA_platform_surfaceless";

/// The library opened at run time.
pub const EGL_LIBRARY: &str = "libEGL.so.1";

/// Everything that can go wrong while creating a context or running a batch.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GlError {
    /// `libEGL.so.1` could not be opened, or lacks EGL 1.5 entry points.
    #[error("cannot load {library}: {detail} (install libegl1 libegl-mesa0 libgl1-mesa-dri)")]
    LibraryMissing {
        /// The library name that was tried.
        library: String,
        /// The loader's message.
        detail: String,
    },
    /// A required EGL client or display extension is absent.
    #[error("EGL extension {extension} is missing ({hint}); available: [{available}]")]
    MissingExtension {
        /// The extension name.
        extension: String,
        /// The extension string that was reported.
        available: String,
        /// What to install or check.
        hint: &'static str,
    },
    /// An EGL call failed.
    #[error("{call} failed: {error} ({hint})")]
    Egl {
        /// The EGL function.
        call: &'static str,
        /// The EGL error (e.g. `BadAlloc`).
        error: String,
        /// What to install or check.
        hint: &'static str,
    },
    /// No EGL config matched the request (an OpenGL-renderable config).
    #[error("eglChooseConfig found no OpenGL-renderable config")]
    NoConfig,
    /// A GL object could not be created, or GL raised an error.
    #[error("{call} failed: {detail}")]
    Gl {
        /// The GL call or step.
        call: String,
        /// The message or GL error code.
        detail: String,
    },
    /// A shader stage did not compile.
    #[error("{stage} shader did not compile:\n{log}\nsource:\n{excerpt}")]
    Compile {
        /// "vertex" or "fragment".
        stage: &'static str,
        /// The driver's info log (line numbers refer to the user body, see [`crate::gl::batch`]).
        log: String,
        /// The source lines the log points at, numbered.
        excerpt: String,
    },
    /// The program did not link.
    #[error("program did not link:\n{log}")]
    Link {
        /// The driver's info log.
        log: String,
    },
    /// The framebuffer is incomplete.
    #[error("framebuffer incomplete: status 0x{status:04X}")]
    Framebuffer {
        /// The `glCheckFramebufferStatus` value.
        status: u32,
    },
    /// An argument is out of range; `field` names it.
    #[error("invalid {field}: {reason}")]
    Input {
        /// The offending argument.
        field: String,
        /// Why it is rejected.
        reason: String,
    },
}

impl GlError {
    /// A short, stable name of the variant (`library_missing`, `missing_extension`, `egl`,
    /// `no_config`, `gl`, `compile`, `link`, `framebuffer`, `input`), for logs and tests.
    pub fn kind(&self) -> &'static str {
        match self {
            GlError::LibraryMissing { .. } => "library_missing",
            GlError::MissingExtension { .. } => "missing_extension",
            GlError::Egl { .. } => "egl",
            GlError::NoConfig => "no_config",
            GlError::Gl { .. } => "gl",
            GlError::Compile { .. } => "compile",
            GlError::Link { .. } => "link",
            GlError::Framebuffer { .. } => "framebuffer",
            GlError::Input { .. } => "input",
        }
    }
}

/// The EGL instance type: EGL 1.5 entry points loaded from a shared library at run time.
type Egl = egl::DynamicInstance<egl::EGL1_5>;

/// A current, headless OpenGL 3.3 core context.
///
/// Created with [`GlContext::new`]; the context is released and destroyed on drop.
/// The EGL display is left initialized, because EGL shares one display per platform
/// across the whole process and other contexts may still use it. For the same reason the
/// EGL library is loaded once per process and never unloaded (see `loaded_egl`).
pub struct GlContext {
    gl: glow::Context,
    egl: &'static Egl,
    display: egl::Display,
    context: egl::Context,
    info: GlInfo,
    _turn: Turn,
    _not_send: PhantomData<*const ()>,
}

/// What the driver says about itself.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GlInfo {
    /// `GL_VENDOR`, e.g. "Mesa".
    pub vendor: String,
    /// `GL_RENDERER`, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    pub renderer: String,
    /// `GL_VERSION`, e.g. "4.5 (Core Profile) Mesa 22.3.6".
    pub version: String,
    /// `GL_SHADING_LANGUAGE_VERSION`.
    pub glsl_version: String,
    /// `GL_MAX_TEXTURE_SIZE`.
    pub max_texture_size: i32,
    /// `GL_MAX_TEXTURE_IMAGE_UNITS` (samplers a fragment shader may read).
    pub max_texture_units: i32,
    /// `GL_MAX_DRAW_BUFFERS`.
    pub max_draw_buffers: i32,
}

impl GlInfo {
    /// True when the renderer is Mesa's llvmpipe software rasterizer.
    pub fn is_llvmpipe(&self) -> bool {
        self.renderer.contains("llvmpipe")
    }
}

fn egl_error(call: &'static str, hint: &'static str) -> impl FnOnce(egl::Error) -> GlError {
    move |e| GlError::Egl { call, error: format!("{e:?}"), hint }
}

impl GlContext {
    /// Creates a headless OpenGL 3.3 core context and makes it current on this thread.
    ///
    /// Returns a [`GlError`] naming the missing piece when libEGL, the Mesa EGL vendor,
    /// the surfaceless platform or the DRI driver is absent. Takes about 25 ms on llvmpipe.
    pub fn new() -> Result<GlContext, GlError> {
        Self::with_library(EGL_LIBRARY)
    }

    /// As [`GlContext::new`], loading EGL from `library` (a file name or path) instead of
    /// `libEGL.so.1`. Errors: [`GlError::LibraryMissing`] if it cannot be opened.
    pub fn with_library(library: &str) -> Result<GlContext, GlError> {
        // khronos-egl unwraps `eglGetError` after a failed call, and glow panics when
        // GL_VERSION is null; a broken driver must still come back as an error.
        match catch_unwind(AssertUnwindSafe(|| Self::create(library))) {
            Ok(result) => result,
            Err(panic) => {
                Err(GlError::Gl { call: "context creation".into(), detail: crate::error::panic_text(&*panic) })
            }
        }
    }

    fn create(library: &str) -> Result<GlContext, GlError> {
        let turn = Turn::take();
        let _one_at_a_time = display_lock();
        let egl = loaded_egl(library)?;
        let client_ext = egl
            .query_string(None, egl::EXTENSIONS)
            .map_err(egl_error(
                "eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)",
                "EGL without client extensions; install libegl-mesa0",
            ))?
            .to_string_lossy()
            .into_owned();
        require_extension(&client_ext, SURFACELESS_EXTENSION, "no Mesa EGL vendor; install libegl-mesa0")?;
        // SAFETY: the surfaceless platform takes EGL_DEFAULT_DISPLAY and no native display.
        let display =
            unsafe { egl.get_platform_display(PLATFORM_SURFACELESS_MESA, egl::DEFAULT_DISPLAY, &[egl::ATTRIB_NONE]) }
                .map_err(egl_error("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)", "install libegl-mesa0"))?;
        egl.initialize(display).map_err(egl_error("eglInitialize", "no usable DRI driver; install libgl1-mesa-dri"))?;
        let display_ext = egl
            .query_string(Some(display), egl::EXTENSIONS)
            .map_err(egl_error("eglQueryString(display, EGL_EXTENSIONS)", ""))?
            .to_string_lossy()
            .into_owned();
        require_extension(
            &display_ext,
            "EGL_KHR_surfaceless_context",
            "the driver cannot make a context current without a surface",
        )?;
        egl.bind_api(egl::OPENGL_API)
            .map_err(egl_error("eglBindAPI(EGL_OPENGL_API)", "Mesa built without desktop GL"))?;
        let config_attribs = [
            egl::SURFACE_TYPE,
            0, // no window, pbuffer or pixmap: the context is surfaceless
            egl::RENDERABLE_TYPE,
            egl::OPENGL_BIT,
            egl::NONE,
        ];
        let config = egl
            .choose_first_config(display, &config_attribs)
            .map_err(egl_error("eglChooseConfig", ""))?
            .ok_or(GlError::NoConfig)?;
        let context_attribs = [
            egl::CONTEXT_MAJOR_VERSION,
            3,
            egl::CONTEXT_MINOR_VERSION,
            3,
            egl::CONTEXT_OPENGL_PROFILE_MASK,
            egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
            egl::NONE,
        ];
        let context = egl
            .create_context(display, config, None, &context_attribs)
            .map_err(egl_error("eglCreateContext(OpenGL 3.3 core)", "the driver lacks OpenGL 3.3 core"))?;
        if let Err(e) = egl.make_current(display, None, None, Some(context)) {
            let _ = egl.destroy_context(display, context);
            return Err(egl_error("eglMakeCurrent(EGL_NO_SURFACE)", "")(e));
        }
        // SAFETY: the context is current on this thread; the loader returns entry points
        // of that context (EGL 1.5 get_proc_address covers core functions too).
        let gl = unsafe {
            glow::Context::from_loader_function(|name| {
                egl.get_proc_address(name).map_or(std::ptr::null(), |f| f as *const std::ffi::c_void)
            })
        };
        let info = read_info(&gl);
        Ok(GlContext { gl, egl, display, context, info, _turn: turn, _not_send: PhantomData })
    }

    /// The glow function table of this context (current on the creating thread).
    pub fn gl(&self) -> &glow::Context {
        &self.gl
    }

    /// Vendor, renderer, versions and limits reported by the driver.
    pub fn info(&self) -> &GlInfo {
        &self.info
    }
}

/// This thread's turn at OpenGL: a process-wide lock, re-entrant per thread, held for the
/// whole life of a [`GlContext`].
///
/// Contexts of one process share one surfaceless display and so one llvmpipe screen. The
/// test suite runs OpenGL tests on parallel threads, each on its own context, and CI runs
/// still died of SIGSEGV among them (1 in about 4 runs) after creation and destruction
/// were serialized. With this turn no two threads ever drive llvmpipe at once; llvmpipe
/// still rasterizes each draw on all its own threads. A thread may hold several
/// contexts (the count is per thread). The commands hold one context per process
/// (`grade` runs each check in its own child), so only the tests wait here.
///
/// A thread that waits longer than [`TURN_PATIENCE`] goes on without the turn, so a
/// thread that holds a context while it waits for another thread that needs one is slow,
/// never a deadlock.
struct Turn;

/// How long a thread waits for its turn before it goes on without it: longer than any
/// one test holds a context under load (the longest, the mutant diagnosis, takes about
/// a minute in a debug build on 2 busy cores).
const TURN_PATIENCE: std::time::Duration = std::time::Duration::from_secs(600);

/// The thread holding the turn and how many of its contexts are alive.
static TURN: std::sync::Mutex<Option<(std::thread::ThreadId, usize)>> = std::sync::Mutex::new(None);
static TURN_FREED: std::sync::Condvar = std::sync::Condvar::new();

impl Turn {
    fn take() -> Turn {
        let me = std::thread::current().id();
        let deadline = std::time::Instant::now() + TURN_PATIENCE;
        let mut holder = TURN.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        loop {
            match holder.as_mut() {
                None => {
                    *holder = Some((me, 1));
                    return Turn;
                }
                Some((owner, count)) if *owner == me => {
                    *count += 1;
                    return Turn;
                }
                Some(_) => {
                    let left = deadline.saturating_duration_since(std::time::Instant::now());
                    if left.is_zero() {
                        return Turn;
                    }
                    holder = TURN_FREED.wait_timeout(holder, left).unwrap_or_else(std::sync::PoisonError::into_inner).0;
                }
            }
        }
    }
}

impl Drop for Turn {
    fn drop(&mut self) {
        let me = std::thread::current().id();
        let mut holder = TURN.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some((owner, count)) = holder.as_mut() {
            if *owner == me {
                *count -= 1;
                if *count == 0 {
                    *holder = None;
                    TURN_FREED.notify_all();
                }
            }
        }
    }
}

/// Held while a context is created or destroyed: the process shares one surfaceless
/// display, and its initialization, context creation and destruction are done one thread
/// at a time (about 25 ms each on llvmpipe; the GL work itself stays parallel, each
/// thread on its own context).
fn display_lock() -> std::sync::MutexGuard<'static, ()> {
    static DISPLAY: std::sync::Mutex<()> = std::sync::Mutex::new(());
    DISPLAY.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The EGL instance of `library`, loaded on first use and kept for the life of the process.
///
/// Unloading is what this prevents. Each context used to load its own instance, and
/// dropping it called `dlclose`. When the last live instance went, glvnd's `libEGL.so.1`
/// could be unloaded, and Mesa's vendor library with it, while the display (never
/// terminated, see [`GlContext`]) and llvmpipe's rasterizer threads lived on. The tests
/// create and drop contexts on parallel threads, and a CI run died of SIGSEGV among them;
/// with one instance per process there is no unloading left to race. Loading is also
/// serialized, so two threads never `dlopen` one library at the same time.
fn loaded_egl(library: &str) -> Result<&'static Egl, GlError> {
    static LOADED: std::sync::Mutex<Vec<(String, &'static Egl)>> = std::sync::Mutex::new(Vec::new());
    let mut loaded = LOADED.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some((_, egl)) = loaded.iter().find(|(name, _)| name == library) {
        return Ok(egl);
    }
    // SAFETY: the library is expected to be an EGL implementation; the loader checks
    // that every EGL 1.5 symbol is present before any call.
    let egl = unsafe { Egl::load_required_from_filename(library) }
        .map_err(|e| GlError::LibraryMissing { library: library.into(), detail: e.to_string() })?;
    let egl: &'static Egl = Box::leak(Box::new(egl));
    loaded.push((library.to_string(), egl));
    Ok(egl)
}

impl Drop for GlContext {
    fn drop(&mut self) {
        let _one_at_a_time = display_lock();
        let _ = self.egl.make_current(self.display, None, None, None);
        let _ = self.egl.destroy_context(self.display, self.context);
    }
}

impl fmt::Debug for GlContext {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("GlContext").field("info", &self.info).finish()
    }
}

fn require_extension(list: &str, extension: &str, hint: &'static str) -> Result<(), GlError> {
    if list.split_whitespace().any(|e| e == extension) {
        Ok(())
    } else {
        Err(GlError::MissingExtension { extension: extension.into(), available: list.into(), hint })
    }
}

fn read_info(gl: &glow::Context) -> GlInfo {
    // SAFETY: plain queries on the current context.
    unsafe {
        GlInfo {
            vendor: gl.get_parameter_string(glow::VENDOR),
            renderer: gl.get_parameter_string(glow::RENDERER),
            version: gl.get_parameter_string(glow::VERSION),
            glsl_version: gl.get_parameter_string(glow::SHADING_LANGUAGE_VERSION),
            max_texture_size: gl.get_parameter_i32(glow::MAX_TEXTURE_SIZE),
            max_texture_units: gl.get_parameter_i32(glow::MAX_TEXTURE_IMAGE_UNITS),
            max_draw_buffers: gl.get_parameter_i32(glow::MAX_DRAW_BUFFERS),
        }
    }
}
