//! `set key value` commands: the limits (`maxdepth`, `maxobjects`,
//! `minsize`, `maxsize`), `seed`, `background`, `colorpool`, `syncrandom`,
//! the viewer's camera settings, and the ones accepted and ignored (the
//! raytracer's, `recursion`, `rng`, `opengl`, `template`).

use super::Parser;
use crate::eisen::syntax::tokens::number;
use crate::eisen::syntax::{colour, Action, CameraSetting, ColourPool, Setting};
use crate::core::{Diagnostic, ParseError, Span};
use glam::DVec3;

impl Parser {
    pub(super) fn set(&mut self, span: Span) -> Result<Action, ParseError> {
        let key = self.next("a setting name after `set`")?;
        let value = self.next(&format!("a value for `set {}`", key.text))?;
        let k = key.text.to_ascii_lowercase();
        let v = value.text.as_str();
        let vl = v.to_ascii_lowercase();
        let int = |what: &str| -> Result<i64, ParseError> {
            match number(v) {
                Some((n, true)) => Ok(n as i64),
                _ => Err(ParseError::single(value.span, format!("`set {what}` expects a whole number, found `{v}`"))),
            }
        };
        let float = |what: &str| -> Result<f64, ParseError> {
            number(v).map(|(n, _)| n).ok_or_else(|| ParseError::single(value.span, format!("`set {what}` expects a number, found `{v}`")))
        };
        let setting = match k.as_str() {
            // Structure Synth's tokenizer rewrites `md` to `maxdepth` before
            // the parser sees it (Tokenizer.cpp:162), so `set md 20` is `set maxdepth 20`.
            "maxdepth" | "md" => Setting::MaxDepth(int("maxdepth")?),
            "weight" | "w" => {
                return Err(ParseError::single(
                    key.span,
                    format!("`{}` is a rule modifier (`rule name w 2 {{ … }}`), not a setting; Structure Synth refuses `set weight` too (EisenParser.cpp:313-315)", key.text),
                ))
            }
            "maxobjects" => Setting::MaxObjects(int("maxobjects")?),
            "minsize" => Setting::MinSize(float("minsize")?),
            "maxsize" => Setting::MaxSize(float("maxsize")?),
            "seed" if vl == "initial" => Setting::Seed(None),
            "seed" => Setting::Seed(Some(int("seed")?)),
            "background" if vl == "random" => {
                return Err(ParseError::single(value.span, "`set background random` is not a colour: Structure Synth (Builder.cpp:352-353) and eisenscript.js both refuse it"))
            }
            "background" => Setting::Background(
                colour::parse(v).ok_or_else(|| ParseError::single(value.span, format!("`set background`: `{v}` is not a colour")))?,
            ),
            "colorpool" => Setting::ColourPool(self.pool(v, value.span)?),
            "syncrandom" => match vl.as_str() {
                "true" => Setting::SyncRandom(true),
                "false" => Setting::SyncRandom(false),
                _ => return Err(ParseError::single(value.span, format!("`set syncrandom` expects true or false, found `{v}`"))),
            },
            "recursion" => {
                self.script.depth_first |= vl == "depth";
                Setting::Ignored
            }
            "rng" if vl == "old" || vl == "new" => Setting::Ignored,
            "translation" | "rotation" | "pivot" | "scale" | "perspective-angle" => Setting::Camera(camera_setting(&k, v, value.span)?),
            "opengl" | "template" => Setting::Ignored,
            // eisenscript.js accepts `set color random` and does nothing with it.
            "color" if vl == "random" => {
                self.script.warnings.push(Diagnostic::warning(key.span, "`set color random` is an eisenscript.js setting that has no effect there either; it is ignored"));
                Setting::Ignored
            }
            _ if k.starts_with("raytracer::") => {
                self.script.warnings.push(Diagnostic::warning(key.span, format!("`set {k}` configures Structure Synth's raytracer; it is ignored")));
                Setting::Ignored
            }
            _ => return Err(ParseError::single(key.span, format!("unknown setting `set {}`", key.text))),
        };
        Ok(Action::Set(setting, span))
    }

    fn pool(&self, v: &str, span: Span) -> Result<ColourPool, ParseError> {
        let lower = v.to_ascii_lowercase();
        match lower.as_str() {
            "randomhue" => return Ok(ColourPool::RandomHue),
            "randomrgb" => return Ok(ColourPool::RandomRgb),
            "greyscale" | "grayscale" => return Ok(ColourPool::Greyscale),
            _ => {}
        }
        if lower.starts_with("image:") {
            return Err(ParseError::single(span, "`set colorpool image:…` samples a local image file, which a render service cannot read; use a `list:` pool"));
        }
        if let Some(list) = v.get(5..).filter(|_| lower.starts_with("list:")) {
            let colours = list
                .split(',')
                .map(|c| colour::parse(c.trim()).ok_or_else(|| ParseError::single(span, format!("`set colorpool list:…`: `{c}` is not a colour"))))
                .collect::<Result<Vec<_>, _>>()?;
            if colours.is_empty() {
                return Err(ParseError::single(span, "`set colorpool list:` needs at least one colour"));
            }
            return Ok(ColourPool::List(colours));
        }
        Err(ParseError::single(span, format!("unknown colour pool `{v}` (known: randomhue, randomrgb, greyscale, list:c1,c2,…)")))
    }

}

/// Parses a viewer setting's value: `[x y z]`, `[9 numbers]` or a number.
fn camera_setting(key: &str, value: &str, span: Span) -> Result<CameraSetting, ParseError> {
    let nums: Vec<f64> = value
        .trim_matches(|c| c == '[' || c == ']')
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|w| !w.is_empty())
        .map(|w| number(w).map(|n| n.0))
        .collect::<Option<_>>()
        .ok_or_else(|| ParseError::single(span, format!("`set {key}`: `{value}` is not a list of numbers")))?;
    let want = match key {
        "rotation" => 9,
        "translation" | "pivot" => 3,
        _ => 1,
    };
    if nums.len() != want {
        return Err(ParseError::single(span, format!("`set {key}` expects {want} number(s), found `{value}`")));
    }
    Ok(match key {
        "translation" => CameraSetting::Translation(DVec3::from_slice(&nums)),
        "pivot" => CameraSetting::Pivot(DVec3::from_slice(&nums)),
        "rotation" => CameraSetting::Rotation(glam::DMat3::from_cols_slice(&nums).transpose()),
        "scale" => CameraSetting::Scale(nums[0]),
        _ => CameraSetting::PerspectiveAngle(nums[0]),
    })
}

