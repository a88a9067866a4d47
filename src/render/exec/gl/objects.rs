//! GL objects that delete themselves: every object the GL executor makes
//! is held by an [`Obj`], which deletes it (with its context current) when
//! dropped, so no error path leaks one.

use std::rc::Rc;

use glow::HasContext;

use super::Context;

/// A kind of GL object, and how to delete one.
pub trait Kind: Copy {
    /// # Safety
    /// `gl` is current and made the object.
    unsafe fn delete(self, gl: &glow::Context);
}

macro_rules! kinds {
    ($($ty:ty => $delete:ident),* $(,)?) => {
        $(impl Kind for $ty {
            unsafe fn delete(self, gl: &glow::Context) {
                // SAFETY: the caller's contract.
                unsafe { gl.$delete(self) }
            }
        })*
    };
}

kinds! {
    glow::NativeBuffer => delete_buffer,
    glow::NativeTexture => delete_texture,
    glow::NativeFramebuffer => delete_framebuffer,
    glow::NativeRenderbuffer => delete_renderbuffer,
    glow::NativeVertexArray => delete_vertex_array,
    glow::NativeProgram => delete_program,
    glow::NativeShader => delete_shader,
    glow::NativeSampler => delete_sampler,
}

/// One GL object, deleted on drop.
pub struct Obj<T: Kind> {
    ctx: Rc<Context>,
    raw: T,
}

impl<T: Kind> Obj<T> {
    /// Takes ownership of `raw`, made on `ctx`.
    pub fn new(ctx: &Rc<Context>, raw: T) -> Obj<T> {
        Obj { ctx: ctx.clone(), raw }
    }

    pub fn raw(&self) -> T {
        self.raw
    }
}

impl<T: Kind> Drop for Obj<T> {
    fn drop(&mut self) {
        if let Ok(gl) = self.ctx.current() {
            // SAFETY: the context is current and made the object.
            unsafe { self.raw.delete(gl) }
        }
    }
}
