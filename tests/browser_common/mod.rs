//! The browser tests' tools: the Chromium binary, one built book per test binary, a page
//! run with a query and its `<pre>` read back, and the book's page data.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use lightlab::book::{self, BuildOptions};

/// The Chromium binary, or `None` (with the reason printed) when there is none and the
/// environment does not require one.
pub fn chromium() -> Option<PathBuf> {
    let require = std::env::var("LIGHTLAB_REQUIRE_BROWSER").is_ok_and(|v| v == "1");
    let candidates: Vec<PathBuf> = match std::env::var_os("LIGHTLAB_CHROMIUM") {
        Some(p) => vec![PathBuf::from(p)],
        None => ["/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"]
            .iter()
            .map(PathBuf::from)
            .collect(),
    };
    match candidates.into_iter().find(|p| p.is_file()) {
        Some(p) => Some(p),
        None if require => panic!("LIGHTLAB_REQUIRE_BROWSER=1 but no Chromium (install the Debian package chromium)"),
        None => {
            println!("skipped: no Chromium found (install the Debian package chromium, or set LIGHTLAB_CHROMIUM)");
            None
        }
    }
}

/// Build a copy of the book once per test process; returns the directory of index.html.
pub fn built_book() -> &'static Path {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    BUILT.get_or_init(|| {
        let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("browser-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        // chapters include compiled code from ../../src and ../../examples
        for code in ["src", "examples", "book", "po"] {
            crate::common::copy_book_tree(&crate_dir.join(code), &dir.join(code));
        }
        let opts = BuildOptions { root: dir.join("book"), force: false, quiet: true, no_solutions: false };
        let report = book::build(&opts).unwrap_or_else(|e| panic!("book build failed: {e}"));
        report.index_html.parent().unwrap().to_path_buf()
    })
}

/// Run headless Chromium on `page?query` and return the text of `<pre id="{pre}">`.
pub fn run_page(browser: &Path, page: &Path, query: &str, pre: &str) -> Result<String, String> {
    static RUN: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUN.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let profile = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("chromium-profile-{}-{run}", std::process::id()));
    let url = format!("file://{}?{query}", page.display());
    let dom = dump_dom(browser, &url, &profile);
    let _ = fs::remove_dir_all(&profile);
    pre_text(&dom?, pre).map_err(|e| format!("{url}: {e}"))
}

/// `?selftest` of `page`, run once per test process: the tests that read the same page's
/// self-check JSON (the figures' test, the exercises' test, the pair box's, the figure
/// mutants') share one Chromium run instead of repeating the page's whole self-check.
/// A test that changes the conditions (a loaded CPU, a changed copy of the book) calls
/// [`run_page`] itself.
pub fn selftest_of(browser: &Path, page: &Path) -> Result<String, String> {
    type Runs = std::collections::HashMap<PathBuf, std::sync::Arc<OnceLock<Result<String, String>>>>;
    static RUNS: std::sync::Mutex<Option<Runs>> = std::sync::Mutex::new(None);
    let cell = {
        let mut runs = RUNS.lock().unwrap_or_else(|e| e.into_inner());
        runs.get_or_insert_with(Default::default).entry(page.to_path_buf()).or_default().clone()
    };
    // a second test asking for the same page waits here for the first run's result
    cell.get_or_init(|| run_page(browser, page, "selftest", "lightlab-selftest")).clone()
}

/// The text of `<pre id="{pre}">` in a dumped DOM, unescaped: the serializer writes `"`,
/// `<`, `>`, `&` and the no-break space (U+00A0, before French `:`) as entities.
pub fn pre_text(dom: &str, pre: &str) -> Result<String, String> {
    let open = format!("<pre id=\"{pre}\"");
    let start = dom.find(&open).ok_or_else(|| format!("no <pre id=\"{pre}\"> in the page"))? + open.len();
    let start = dom[start..].find('>').ok_or("unterminated <pre> tag")? + start + 1;
    let end = dom[start..].find("</pre>").ok_or("unterminated <pre>")? + start;
    Ok(dom[start..end]
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&nbsp;", "\u{a0}")
        .replace("&amp;", "&"))
}

/// Run headless Chromium on `url` with the browser profile (storage included) in `profile`,
/// and return the DOM it dumps once the page settled.
pub fn dump_dom(browser: &Path, url: &str, profile: &Path) -> Result<String, String> {
    dump_dom_within(browser, url, profile, Duration::from_secs(600))
}

/// [`dump_dom`] with its own hang guard: a Chromium still running after `limit` is killed
/// and the run is an error (a page whose checker froze the tab never settles).
pub fn dump_dom_within(browser: &Path, url: &str, profile: &Path, limit: Duration) -> Result<String, String> {
    dump_dom_loaded(browser, url, profile, limit, 0)
}

/// [`run_page`] with `busy` processes spinning on the CPU while Chromium runs, and only
/// then: they start once this page has Chromium's turn, so they never slow another test's
/// page while this one waits.
pub fn run_page_under_load(browser: &Path, page: &Path, query: &str, pre: &str, busy: usize) -> Result<String, String> {
    let profile = profile_dir("loaded");
    let url = format!("file://{}?{query}", page.display());
    let dom = dump_dom_loaded(browser, &url, &profile, Duration::from_secs(600), busy);
    let _ = fs::remove_dir_all(&profile);
    pre_text(&dom?, pre).map_err(|e| format!("{url}: {e}"))
}

/// Busy processes, stopped when dropped.
struct Busy(Vec<std::process::Child>);

impl Busy {
    fn start(n: usize) -> Busy {
        Busy((0..n).filter_map(|_| Command::new("sh").args(["-c", "while :; do :; done"]).spawn().ok()).collect())
    }
}

impl Drop for Busy {
    fn drop(&mut self) {
        for child in &mut self.0 {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

/// [`dump_dom_within`] with `busy` processes loading the CPU during this page's turn.
fn dump_dom_loaded(browser: &Path, url: &str, profile: &Path, limit: Duration, busy: usize) -> Result<String, String> {
    // one Chromium at a time: several SwiftShader instances on two cores left pages
    // without their self-check output (the tests run in parallel threads)
    static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let load = Busy::start(busy);
    assert_eq!(load.0.len(), busy, "could not start {busy} busy processes");
    let mut child = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            // virtual time: the page's timers and image decoding run without waiting; the
            // budget only bounds them (real rendering time is not counted)
            "--virtual-time-budget=120000",
            "--dump-dom",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(url)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("starting {}: {e}", browser.display()))?;
    // read the DOM while Chromium writes it: a full pipe would block it
    let mut stdout = child.stdout.take().ok_or("no stdout")?;
    let reader = std::thread::spawn(move || {
        let mut buf = Vec::new();
        std::io::Read::read_to_end(&mut stdout, &mut buf).map(|_| buf)
    });
    let start = Instant::now();
    loop {
        if child.try_wait().map_err(|e| e.to_string())?.is_some() {
            break;
        }
        // a hang guard, not a performance bound
        if start.elapsed() > limit {
            let _ = child.kill();
            return Err(format!("{url}: Chromium did not finish in {} s", limit.as_secs()));
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let out = reader.join().map_err(|_| "reader thread panicked")?.map_err(|e| e.to_string())?;
    Ok(String::from_utf8_lossy(&out).into_owned())
}

/// The chapter pages (every `.html` at the top of the build but the print, 404 and toc pages).
pub fn chapter_pages(html: &Path) -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = fs::read_dir(html)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "html"))
        .filter(|p| !["print.html", "404.html", "toc.html"].contains(&p.file_name().unwrap().to_str().unwrap()))
        .collect();
    pages.sort();
    pages
}

pub fn copy_all(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for entry in fs::read_dir(from).unwrap().flatten() {
        let (src, dst) = (entry.path(), to.join(entry.file_name()));
        if src.is_dir() {
            copy_all(&src, &dst);
        } else {
            fs::copy(&src, &dst).unwrap();
        }
    }
}

/// The page data of exercise `id` in a built book (`generated/live/exercise-<id>.js`).
pub fn exercise_data(html: &Path, id: &str) -> serde_json::Value {
    let js = fs::read_to_string(html.join(format!("generated/live/exercise-{id}.js"))).unwrap();
    let (_, body) = js.split_once("\"] = ").unwrap();
    serde_json::from_str(body.trim_end().trim_end_matches(';')).unwrap()
}

/// A fresh browser profile directory for a test that keeps it across runs.
pub fn profile_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("chromium-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    dir
}

/// `?exercise-state` of `page` (with `fragment` after `#`) in `profile`: the JSON the learner
/// script writes once the page's link was handled, and the whole DOM.
pub fn exercise_state(
    browser: &Path,
    page: &Path,
    query: &str,
    fragment: &str,
    profile: &Path,
) -> (serde_json::Value, String) {
    let url = format!("file://{}?{query}&exercise-state{fragment}", page.display());
    let dom = dump_dom(browser, &url, profile).unwrap_or_else(|e| panic!("{e}"));
    let text = pre_text(&dom, "lightlab-exercise-state").unwrap_or_else(|e| panic!("{url}: {e}"));
    (serde_json::from_str(&text).unwrap_or_else(|e| panic!("{url}: {e}: {text}")), dom)
}

/// The figure data of live figure `id` in a built book (`generated/live/<id>.js`).
pub fn figure_data(html: &Path, id: &str) -> serde_json::Value {
    let js = fs::read_to_string(html.join(format!("generated/live/{id}.js"))).unwrap();
    let (_, body) = js.split_once("] = ").unwrap();
    serde_json::from_str(body.trim_end().trim_end_matches(';')).unwrap()
}

/// Deflate's stored blocks (RFC 1951, 3.2.4) around `bytes`: a valid deflate-raw stream
/// that the test writes without a compressor.
pub fn stored_deflate(bytes: &[u8]) -> Vec<u8> {
    let chunks: Vec<&[u8]> = if bytes.is_empty() { vec![&[][..]] } else { bytes.chunks(65_535).collect() };
    let mut out = Vec::new();
    for (k, chunk) in chunks.iter().enumerate() {
        out.push(u8::from(k + 1 == chunks.len()));
        let len = u16::try_from(chunk.len()).unwrap();
        out.extend(len.to_le_bytes());
        out.extend((!len).to_le_bytes());
        out.extend_from_slice(chunk);
    }
    out
}

/// base64url without padding (RFC 4648, 5).
pub fn base64url(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    let mut s = String::new();
    for c in bytes.chunks(3) {
        let n =
            (u32::from(c[0]) << 16) | (u32::from(*c.get(1).unwrap_or(&0)) << 8) | u32::from(*c.get(2).unwrap_or(&0));
        for k in 0..=c.len() {
            s.push(ABC[(n >> (18 - 6 * k)) as usize & 63] as char);
        }
    }
    s
}
